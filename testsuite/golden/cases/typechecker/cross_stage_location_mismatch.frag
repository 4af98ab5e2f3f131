// WITH: typechecker/inputs/stage_located.vert
#version 410 core
#include <safegi/prelude.sgl>
space world;
layout(location = 1) in spectrum<irradiance> E;
in VertexData {
    point<world> P;
    float<length> r;
} fs_in;
out vec4 c;
void main() { c = vec4(E * fs_in.r, 1.0); }
