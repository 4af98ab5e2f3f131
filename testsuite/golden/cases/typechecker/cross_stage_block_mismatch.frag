// WITH: typechecker/inputs/stage_located.vert
#version 410 core
#include <safegi/prelude.sgl>
space world;
space object;
layout(location = 1) in spectrum<radiance> L;
in VertexData {
    point<object> P;
    float<length> r;
} fs_in;
out vec4 c;
void main() { c = vec4(L, 1.0); }
