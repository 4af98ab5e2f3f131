#version 330 core
#include <safegi/prelude.sgl>
uniform sampler2D<float<length>> depth;
uniform samplerCube<spectrum<radiance>> env;
out vec4 c;
void main() { c = vec4(texture(env, vec3(0.0, 0.0, 1.0)).rgb * texture(depth, vec2(0.5)).r, 1.0); }
