#version 450
#include <safegi/prelude.sgl>
// A node-graph material in a real-time pipeline: a rim (Fresnel) emission
// from the cosine between the normal and the view direction (fragment to
// camera).
space world;

uniform point<world> cameraPosWS;
uniform spectrum<radiance> rimRadiance;
uniform float<1> rimPower;

in point<world, shaded> positionWS;
in normal<world> normalWS;
out vec4 fragColor;

void main() {
    vec3 N = normalize(normalWS);
    vec3 V = normalize(cameraPosWS - positionWS);
    float NdotV = clamp(dot(N, V), 0.0, 1.0);
    float rim = pow(1.0 - NdotV, rimPower);
    fragColor = vec4(rimRadiance * rim, 1.0);
}
