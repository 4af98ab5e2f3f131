#version 330 core
#include <safegi/prelude.sgl>
space world; space camera; space ndc;
// Interpolated and uniform emission plus an environment lookup, exposed and tinted.
in spectrum<radiance> Lv;
uniform spectrum<radiance> Le;
uniform float exposure;
uniform spectrum<1> tint[2];
uniform sampler2D<spectrum<radiance>> environment;
uniform map<world, camera> cameraFromWorld;
layout(std140) uniform Camera { map<world, camera> viewFromWorld; float<length> focalLength; } camera;
layout(location = 0) out spectrum<radiance> color;
void main() {
  color = (Lv + Le + texture(environment, vec2(0.5)).rgb) * exposure * tint[0] * tint[1];
}
