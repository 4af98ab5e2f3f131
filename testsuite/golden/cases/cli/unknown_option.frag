// RAW
// ARGS: --frobnicate
#version 330 core
void main() {}
