#version 300 es
// Issue 46, class 3: in ES an undefined macro in #if is an error only where
// glslang evaluates it: not on the right of && after 0 nor of || after 1, and
// then not for the rest of that level (`0 && X || Y`: Y is evaluated, as 0,
// and only warned about). Parentheses start a level of their own.
precision mediump float;
out vec4 color;
#if defined(USE_FOG) && USE_FOG
#error fog is not defined
#endif
#if !defined(QUALITY) || QUALITY > 2
#define SAMPLES 4
#endif
#if 0 && (NOT_DEFINED + 1) || ALSO_NOT_DEFINED
#error not taken
#endif
#if 1 == 1 || NOT_DEFINED
void main() { color = vec4(float(SAMPLES)); }
#endif
