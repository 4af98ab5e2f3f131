#version 330 core
#include <safegi/prelude.sgl>
// A simulator's PBR fragment shader, lit in camera space: a point light's
// range window and falloff depend on the distance from the light to the
// shaded point, which does not change when the camera moves.
space camera;

uniform point<camera> lightPosition;                 // the light, carried to camera space
uniform vec3 lightColor;
uniform float<length> lightRange;
uniform vec3 baseColor;

in point<camera, shaded> position;
in normal<camera> normal;
out vec4 fragmentColor;

void main() {
    float dist = length(lightPosition);
    float window = clamp(1.0 - pow(dist / max(lightRange, 0.0001), 4.0), 0.0, 1.0);
    float attenuation = window * window / (1.0 + dist * dist);
    vec3 light = normalize(lightPosition - position);
    float NdotL = max(dot(normalize(normal), light), 0.0);
    vec3 finalColor = baseColor * lightColor * attenuation * NdotL;
    fragmentColor = vec4(finalColor, 1.0);
}
