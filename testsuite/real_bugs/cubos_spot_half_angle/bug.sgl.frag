#version 330 core
#include <safegi/prelude.sgl>
// An engine's spot light whose angles are the full angles between the cone's
// edges (as the shadow pass uses them): the cone test compares with the
// cosines of the half angles.
space world;

uniform point<world> spotPosition;
uniform direction<world> spotDirection;             // the cone's axis
uniform spectrum<intensity> spotIntensity;
uniform float<angle> spotAngle;                     // full outer angle between the edges
uniform float<angle> innerSpotAngle;                // full inner angle
uniform spectrum<brdf> albedo;

in point<world, shaded> fragPos;
in normal<world> fragNormal;
out vec4 color;

void main() {
    vec3 toLight = spotPosition - fragPos;
    float d = length(toLight);
    vec3 L = normalize(toLight);
    float spotCos = dot(-L, spotDirection);
    float outerCos = cos(spotAngle);
    float innerCos = cos(innerSpotAngle);
    float cone = clamp((spotCos - outerCos) / (innerCos - outerCos), 0.0, 1.0);
    float NdotL = max(dot(normalize(fragNormal), L), 0.0);
    float<solid_angle / (area * proj)> falloff = float<solid_angle / (area * proj)>(1.0 / (d * d));
    color = vec4(albedo * spotIntensity * falloff * NdotL * cone, 1.0);
}
