// found by scripts/fuzz-compiler.sh (text form of the same input)
#version 330 core
uniform ËËË float x;
void main() {}
