// RAW
// ARGS: --aml
#version 450
void main() {}
