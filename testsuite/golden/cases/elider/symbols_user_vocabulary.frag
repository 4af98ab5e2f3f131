// SYMBOLS
#version 420 core
dimension mass;
dimension length;
dimension density = mass / length^3;
unit gram : mass = 0.001;
space lab;
uniform float<density> rho;
layout(binding = 2) uniform sampler2D<float<mass>> masses;
uniform point<lab> origin;
out vec4 c;
void main() { c = vec4(origin, rho * float<length^3>(1.0) / (1.0 * gram)); }
