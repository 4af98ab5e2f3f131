#version 460
#include <safegi/prelude.sgl>
// A ray-traced game renderer's direct light from an emissive polygon: a
// point sampled uniformly on the polygon stands for the whole area, so its
// radiance is weighted by the solid angle the area subtends, A cos(theta_l)
// / d^2, and by the receiver's cosine.
space world;

uniform spectrum<radiance> emissive;
uniform float<area> polyArea;
uniform point<world> samplePoint;           // on the emissive polygon
uniform normal<world> polyNormal;
uniform spectrum<brdf> albedoOverPi;

flat in point<world, shaded> hitPos;
flat in normal<world> hitNormal;
out vec4 outColor;

void main() {
    vec3 toLight = samplePoint - hitPos;
    float d = length(toLight);
    vec3 L = toLight / d;
    float cosSurf = max(dot(hitNormal, L), 0.0);
    float cosLight = max(dot(polyNormal, -L), 0.0);
    spectrum<radiance> Lo = albedoOverPi * emissive * cosSurf * polyArea * cosLight * inverse_square(d);
    outColor = vec4(Lo, 1.0);
}
