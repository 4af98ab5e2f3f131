#version 330 core
#include <safegi/prelude.sgl>
// Next-event estimation toward a point light in a glTF path tracer: the
// shadow ray must stop at the light. (The scene's occluder is one sphere here.)
space world;

uniform point<world> lightPosition;
uniform spectrum<intensity> lightIntensity;
uniform spectrum<brdf> bsdfValue;
uniform point<world> occluderCenter;
uniform float<length> occluderRadius;

flat in point<world, shaded> P;
flat in normal<world> N;
out vec4 fragColor;

bool occluded(point<world> origin, direction<world> dir, float<length> tMax) {
    vec3 oc = origin - occluderCenter;
    float b = dot(oc, dir);
    float c = dot(oc, oc) - occluderRadius * occluderRadius;
    float disc = b * b - c;
    if (disc < 0.0) return false;
    float t = -b - sqrt(disc);
    return t > 0.0 && t < tMax;
}

void main() {
    vec3 toLight = lightPosition - P;
    float lightDist = length(toLight);
    vec3 L = normalize(toLight);
    float tMax = 1e32;
    float visibility = occluded(P, L, tMax) ? 0.0 : 1.0;
    float cosTheta = max(dot(N, L), 0.0);
    spectrum<radiance> contrib = bsdfValue * lightIntensity * inverse_square(lightDist) * cosTheta * visibility;
    fragColor = vec4(contrib, 1.0);
}
