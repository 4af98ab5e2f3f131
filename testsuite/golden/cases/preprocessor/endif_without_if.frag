#version 330 core
#endif
void main() {}
