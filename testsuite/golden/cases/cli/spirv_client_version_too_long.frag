// RAW
// ARGS: -V12345678901234 -o /dev/null
// Not a version glslangValidator takes (-V takes a number); here it is not
// -V at all, so it is an unknown option, never a crash.
#version 450
void main() {}
