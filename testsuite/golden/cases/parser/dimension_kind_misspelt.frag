#version 330 core
// The one kind a base dimension may be given is `ratio`.
dimension texel : radio;
void main() {}
