#version 330 core
out vec4 c;
void f() { int a = ; }
void g() { float b = 1.0 +; }
void main() { c = vec4(1.0) }
