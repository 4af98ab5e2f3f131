#version 330 core
// The one property a space may be given is `eye`.
space view : camera;
void main() {}
