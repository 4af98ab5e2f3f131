#version 330 core
#include <safegi/prelude.sgl>
// A PBR point light given by its luminous power (lumens, as light bulbs are
// sold): the luminous intensity the shading uses is that power spread over
// the full sphere, I = P / 4 pi sr.
space world;

uniform point<world> lightPosition;
uniform float<power> lightLumens;
uniform spectrum<1> lightColor;
uniform float<length> lightRange;
uniform spectrum<1> baseColor;

in point<world, shaded> worldPosition;
in normal<world> worldNormal;
out vec4 fragColor;

const float<brdf> FRAC_1_PI = float<brdf>(0.3183098861837907);
const float<solid_angle> FULL_SPHERE = float<solid_angle>(4.0 * 3.141592653589793);

void main() {
    vec3 intensity = lightColor * lightLumens / FULL_SPHERE;
    vec3 toLight = lightPosition - worldPosition;
    float distance = length(toLight);
    vec3 L = normalize(toLight);
    float NoL = clamp(dot(normalize(worldNormal), L), 0.0, 1.0);
    float factor = distance / lightRange;
    float window = clamp(1.0 - factor * factor * factor * factor, 0.0, 1.0);
    float attenuation = float<solid_angle / (area * proj)>(window * window / (distance * distance));
    spectrum<radiance> color = baseColor * FRAC_1_PI * intensity * attenuation * NoL;
    fragColor = vec4(color, 1.0);
}
