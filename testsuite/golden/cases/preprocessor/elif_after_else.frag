#version 330 core
#if 1
#else
#elif 1
#endif
void main() {}
