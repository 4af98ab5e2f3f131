// ARGS: --diagnostics-format=json
#version 330 core
#include <safegi/prelude.sgl>
void main() { float<length> d = 1.0 * second; }
