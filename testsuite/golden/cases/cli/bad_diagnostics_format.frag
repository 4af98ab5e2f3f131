// RAW
// ARGS: --diagnostics-format=xml
#version 330 core
void main() {}
