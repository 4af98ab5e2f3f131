// RAW
// ARGS: --error-limit=many
#version 330 core
void main() {}
