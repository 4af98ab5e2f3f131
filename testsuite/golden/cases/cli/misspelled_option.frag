// RAW
// ARGS: --version-typo
#version 330 core
void main() {}
