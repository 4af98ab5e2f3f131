#version 100
precision mediump float;
#include "inputs/twice.glsl"
void main() { gl_FragColor = vec4(twice(0.5)); }
