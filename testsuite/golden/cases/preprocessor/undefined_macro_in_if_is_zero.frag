#version 330 core
out vec4 c;
#if UNDEFINED_THING
void main() { c = vec4(0.0); }
#else
void main() { c = vec4(1.0); }
#endif
