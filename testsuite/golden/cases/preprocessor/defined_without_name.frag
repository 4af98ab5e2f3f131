#version 330 core
#if defined()
#endif
void main() {}
