// ARGS: --diagnostics-format=json
// found by scripts/fuzz-compiler.sh: a message quoting bytes that are not UTF-8 made the JSON writer throw
#version 330 core
uniform ËËË float x;
void main() {}
