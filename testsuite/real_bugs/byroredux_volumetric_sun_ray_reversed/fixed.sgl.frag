#version 450
#include <safegi/prelude.sgl>
// A game-engine rebuild's volumetric fog: each froxel's in-scattered sunlight
// is the sun's irradiance times the fraction that reaches the froxel, found by
// marching a few steps from the froxel toward the sun through the density
// volume. The host uploads the direction toward the sun.
space world;

uniform direction<world, toward> sunDirection;     // toward the sun
uniform spectrum<irradiance> sunIrradiance;
uniform sampler3D density;
uniform point<world> volumeOrigin;
uniform float<length> volumeSize;
uniform float<length> stepLength;

in point<world> froxelCenter;
out vec4 inScatter;

float sunVisibility(point<world> p, direction<world, toward> toSun) {
    float vis = 1.0;
    for (int i = 1; i <= 8; ++i) {
        vec3 q = p + toSun * (float(i) * stepLength);
        vis *= 1.0 - texture(density, (q - volumeOrigin) / volumeSize).r;
    }
    return vis;
}

void main() {
    vec3 toSun = normalize(sunDirection);
    float vis = sunVisibility(froxelCenter, toSun);
    inScatter = vec4(sunIrradiance * vis, 1.0);
}
