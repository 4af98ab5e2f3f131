// ARGS: --diagnostics-format=json
// found by scripts/fuzz-compiler.sh: F5 is not a UTF-8 lead byte (RFC 3629)
#version 330 core
space light_ÄõŠ‘–™rm map;
void main() {}
