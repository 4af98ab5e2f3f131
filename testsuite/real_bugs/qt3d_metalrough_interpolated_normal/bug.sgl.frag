#version 330 core
#include <safegi/prelude.sgl>
// Qt 3D's metal/rough PBR material, fragment stage: the interpolated world
// normal is renormalized once, then used for every light, with the view
// direction toward the eye, in a GGX specular and a Lambertian diffuse term.
space world;

const float M_PI = 3.14159265358979;

uniform point<world> eyePosition;
uniform point<world> lightPosition;
uniform spectrum<intensity> lightIntensity;
uniform vec3 baseColor;
uniform float metalness;
uniform float roughness;

in point<world, shaded> worldPosition;
in normal<world> worldNormal;
out vec4 fragColor;

vec3 pbrModel(const in point<world, shaded> wPosition, const in normal<world> n,
              const in direction<world, away> v, const in float alpha)
{
    vec3 toLight = lightPosition - wPosition;
    direction<world, away> s = normalize(toLight);
    vec3 h = normalize(s + v);
    float sDotN = max(dot(s, n), 0.0);
    float hDotN = max(dot(h, n), 0.0);
    float a2 = alpha * alpha;
    float d = hDotN * hDotN * (a2 - 1.0) + 1.0;
    float D = a2 / (M_PI * d * d);
    vec3 F0 = mix(vec3(0.04), baseColor, metalness);
    vec3 diffuseColor = (1.0 - metalness) * baseColor;
    vec3 color = (diffuseColor / M_PI + F0 * D / 4.0) * lightIntensity * sDotN * inverse_square(length(toLight));
    return color;
}

void main()
{
    float alpha = roughness * roughness;
    vec3 wNormal = worldNormal;
    vec3 worldView = normalize(eyePosition - worldPosition);
    vec3 cLinear = pbrModel(worldPosition, wNormal, worldView, alpha);
    fragColor = vec4(cLinear, 1.0);
}
