// ARGS: --error-limit 2
#version 330 core
void main() { a = 1; b = 2; c = 3; d = 4; }
