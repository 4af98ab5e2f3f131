#version 330 core
out vec4 c;
#if (3 * 4 + 1) % 5 == 3 && defined(GL_core_profile) && __VERSION__ >= 330
void main() { c = vec4(1.0); }
#else
#error wrong branch
#endif
