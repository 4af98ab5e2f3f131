// RAW
// ARGS: --glsl-version 340
// glslangValidator 12: "glslangValidator: Error: --glsl-version expected one of: 100, 110, 120, 130,
// 140, 150, 300es, 310es, 320es, 330 400, 410, 420, 430, 440, 450, 460 (use -h for usage)" (exit 1).
#version 330 core
void main() {}
