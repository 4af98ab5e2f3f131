#version 330 core
#if 1 / 0
#endif
void main() {}
