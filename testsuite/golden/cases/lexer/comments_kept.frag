#version 330 core
// a line comment with <float> in it
out vec4 c; /* block
 comment spanning lines */
void main() { c = vec4(1.0); } // trailing
