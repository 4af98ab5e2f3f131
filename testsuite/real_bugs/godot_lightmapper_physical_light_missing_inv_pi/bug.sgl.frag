#version 450
#include <safegi/prelude.sgl>
// A lightmapper's direct light from a directional light with physical light
// units: its energy is an illuminance on a surface facing it, and the
// reflected radiance baked into the map is that times the Lambert BRDF,
// albedo / pi, and the receiver's cosine (the real-time renderer divides by
// pi in its BRDF; the baker must too).
space world;

uniform spectrum<irradiance / proj> lightEnergy;   // lux on a surface facing the light
uniform direction<world> toLight;
uniform spectrum<1> albedo;

flat in normal<world> hitNormal;
out vec4 bakedLight;

const float<brdf> INV_PI = float<brdf>(0.3183098861837907);

void main() {
    float NdotL = max(dot(hitNormal, toLight), 0.0);
    spectrum<radiance> light = albedo * lightEnergy * NdotL;
    bakedLight = vec4(light, 1.0);
}
