#version 300 es
#include <safegi/prelude.sgl>
// A web engine's spot light loaded from a glTF file: KHR_lights_punctual
// gives the cone angles in radians, the engine keeps them in degrees; when the
// file leaves the outer angle out, the default is a quarter turn's half, 45
// degrees. The shader turns the angle back into the cosine it compares with.
precision highp float;
space world;

uniform float<angle> gltfOuterConeAngle;      // KHR_lights_punctual, radians
uniform bool hasOuterConeAngle;
uniform point<world> lightPos;
uniform direction<world> spotDirection;       // the way the light travels
uniform spectrum<intensity> lightColor;

in point<world, shaded> vPosition;
in normal<world> vNormal;
out vec4 fragColor;

void main() {
    float<angle in degree> outerConeAngle = hasOuterConeAngle ? degrees(gltfOuterConeAngle) : float<angle in degree>(45.0);
    float cosOuter = cos(radians(outerConeAngle));
    vec3 toLight = lightPos - vPosition;
    vec3 L = normalize(toLight);
    float cd = dot(-L, spotDirection);
    float spot = smoothstep(cosOuter, mix(cosOuter, 1.0, 0.1), cd);
    float NdotL = max(dot(normalize(vNormal), L), 0.0);
    spectrum<irradiance> E = lightColor * spot * NdotL * inverse_square(length(toLight));
    fragColor = vec4(E, 1.0);
}
