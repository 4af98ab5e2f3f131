#version 330 core
#include <safegi/prelude.sgl>
// A cube map may name the space of its lookup direction: a world environment looked up by an
// object-space normal is told; a cube map without a space takes any; a 2D map has no space.
space object;
space world;
uniform samplerCube<spectrum<radiance>, world> environment;
uniform samplerCube<spectrum<radiance>> anyCube;
uniform sampler2D<float<length>, world> bad2d;
in normal<world> N;
in normal<object> nObj;
out vec4 c;
void main() {
  spectrum<radiance> a = texture(environment, N).rgb;
  spectrum<radiance> b = texture(environment, nObj).rgb;
  spectrum<radiance> d = texture(anyCube, nObj).rgb;
  c = vec4(a + b + d, 1.0);
}
