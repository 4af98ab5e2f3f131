#version 410 core
#include <safegi/prelude.sgl>
space world;
layout(location = 1) out spectrum<radiance> radianceOut;
out VertexData {
    point<world> P;
    float<length> r;
} vs_out;
void main() {
    radianceOut = spectrum<radiance>(0.0);
    vs_out.P = point<world>(0.0);
    vs_out.r = 0.0;
    gl_Position = vec4(0.0);
}
