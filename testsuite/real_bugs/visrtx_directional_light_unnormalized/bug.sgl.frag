#version 330 core
#include <safegi/prelude.sgl>
// A scientific-visualization ray tracer's directional light: the application
// sets the light's travel direction with any length, so the renderer
// normalizes it before the cosine at the surface; the light's irradiance is
// given on a plane facing it.
space world;

uniform vector<world, 1, toward> lightDirection;   // travel direction, any length
uniform spectrum<irradiance / proj> lightIrradiance;
uniform spectrum<brdf> diffuseBrdf;

in normal<world> vNormal;
out vec4 fragColor;

void main() {
    vec3 dir = lightDirection;
    vec3 n = normalize(vNormal);
    float cosL = max(dot(n, -dir), 0.0);
    spectrum<radiance> L = diffuseBrdf * lightIrradiance * cosL;
    fragColor = vec4(L, 1.0);
}
