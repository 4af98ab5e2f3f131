#version 330 core
#include <safegi/prelude.sgl>
// A virtual-world client's day cycle: the sun's yaw and pitch come from
// keyframes baked in another engine of the other handedness, so a half turn
// is added to the yaw before the direction toward the sun is built; the sky
// disc and the sunlight use that one direction (so shadows fall away from the
// visible sun).
space world;

uniform float<angle> bakedSunYaw;
uniform float<angle> bakedSunPitch;
uniform spectrum<irradiance / proj> sunIrradiance;
uniform spectrum<brdf> albedo;

in normal<world> vNormal;
out vec4 fragColor;

void main() {
    float yaw = bakedSunYaw + 3.14159265;
    direction<world, away> toSun = vec3(cos(bakedSunPitch) * sin(yaw), sin(bakedSunPitch),
                                        cos(bakedSunPitch) * cos(yaw));
    vec3 n = normalize(vNormal);
    float cosSun = max(dot(n, toSun), 0.0);
    spectrum<radiance> L = albedo * sunIrradiance * cosSun;
    fragColor = vec4(L, 1.0);
}
