#version 330 core
#include <safegi/prelude.sgl>
// A body-tracking library's preview rasterizer shades each pixel with the
// cosine between the light direction and the normal in eye (camera) space.
// Normals reach eye space through the world-to-eye rotation, so the lights,
// given in world space, must go through the same world-to-eye map.
space world;
space camera : eye;

uniform rigidmap<world, camera> eyeFromWorld;
uniform rigidmap<camera, world> worldFromEye;    // also at hand: the camera's pose
uniform direction<world, away> lightDirWorld;    // toward the light
uniform spectrum<irradiance / proj> lightColor;
uniform spectrum<brdf> albedo;

in normal<camera> normalEye;
out vec4 fragColor;

void main() {
    vec3 lightDirEye = (worldFromEye * vec4(lightDirWorld, 0.0)).xyz;
    vec3 n = normalize(normalEye);
    float cosL = max(dot(lightDirEye, n), 0.0);
    spectrum<radiance> L = albedo * lightColor * cosL;
    fragColor = vec4(L, 1.0);
}
