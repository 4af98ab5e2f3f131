#version 300 es
// Issue 46, class 3: where glslang evaluates an undefined macro in an ES #if it
// is an error ("undefined macro in expression not allowed in es profile"): on
// the left of && and ||, after || whose left side is not exactly 1 (`2 || X`),
// and outside the parentheses that short-circuited.
precision mediump float;
out vec4 color;
#if USE_FOG && defined(USE_FOG)
#endif
#if defined(QUALITY) || QUALITY
#endif
#if 2 || LEVEL
#endif
#if (defined(FAST) && FAST) || SLOW
#endif
void main() { color = vec4(1.0); }
