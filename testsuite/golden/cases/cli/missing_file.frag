// RAW
// ARGS: cli/does_not_exist.frag
#version 330 core
void main() {}
