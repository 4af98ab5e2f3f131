#version 330 core
#include <safegi/prelude.sgl>
// A ray tracer's refraction into a glass surface, written as a fragment
// shader: refract() takes the ratio n1 / n2 of the indices on the incident
// side and the transmitted side, so a ray entering glass from air bends
// with 1 / ior.
space world;

uniform samplerCube<spectrum<radiance>, world> environment;
uniform float<1> ior;                  // of the glass, air is 1
uniform point<world> eye;

in point<world, shaded> vPosition;
in normal<world> vNormal;               // outward
out vec4 fragColor;

void main() {
    direction<world, toward> I = normalize(vPosition - eye);
    normal<world> n = normalize(vNormal);
    float<1> eta = ior;           // n_air / n_glass
    direction<world> T = refract(I, n, eta);
    spectrum<radiance> L = texture(environment, T).rgb;
    fragColor = vec4(L, 1.0);
}
