#version 330 core
#include <safegi/prelude.sgl>
space object;
space world;
uniform map<object, world> M;
layout(location = 0) in point<object> p;
layout(location = 1) in normal<object> n;
out normal<world> N;
void main() { N = M * n; gl_Position = vec4(M * p, 1.0); }
