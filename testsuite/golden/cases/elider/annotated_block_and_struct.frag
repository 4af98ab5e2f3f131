#version 330 core
#include <safegi/prelude.sgl>
space world;
struct Light { point<world> p; spectrum<intensity> I; };
layout(std140) uniform Scene { map<world, world> M; float<length> r; } scene;
uniform Light light;
out vec4 c;
void main() { c = vec4(light.I * scene.r, 1.0); }
