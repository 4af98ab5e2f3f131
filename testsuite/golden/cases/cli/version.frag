// RAW
// ARGS: --version
#version 330 core
void main() {}
