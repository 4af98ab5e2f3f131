#version 330 core
#include <safegi/prelude.sgl>
// A rendering-API back end's point light: the API specifies the light's
// intensity in W/sr, so the irradiance it gives a surface falls off with the
// inverse square of the distance and the receiver's cosine; the value is not
// an irradiance (W/m^2) to be used as it is.
space world;

uniform point<world> lightPosition;
uniform spectrum<intensity> lightIntensity;        // W/sr, as the API defines it
uniform spectrum<brdf> diffuseBrdf;                 // albedo / pi

in point<world, shaded> hitPosition;
in normal<world> hitNormal;
out vec4 color;

void main() {
    vec3 toLight = lightPosition - hitPosition;
    float d = length(toLight);
    vec3 L = toLight / d;
    float cosTheta = max(dot(normalize(hitNormal), L), 0.0);
    spectrum<irradiance> E = lightIntensity * cosTheta;
    spectrum<radiance> Lo = diffuseBrdf * E;
    color = vec4(Lo, 1.0);
}
