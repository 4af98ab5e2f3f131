#version 330 core
#include <safegi/prelude.sgl>
// GLSL's own errors are found before the driver sees the shader.
space world;

uniform spectrum<radiance> Le;
uniform spectrum<brdf> Kd;
uniform direction<world> wi;
uniform float<solid_angle> dw;

in normal<world> N;
out vec4 fragColor;

void main() {
    normal<world> n = normalize(N);
    float<proj> cosTheta = max(dot(n, wi));
    spectrum<radiance> L = Kd * Le * cosTheta * dw;
    fragColor = vec4(L, 1.0);
}
