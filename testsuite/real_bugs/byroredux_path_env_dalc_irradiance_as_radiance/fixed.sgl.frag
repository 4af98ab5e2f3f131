#version 330 core
#include <safegi/prelude.sgl>
// Environment term of a path tracer for a ray that escapes the scene in a cell
// lit by a directional-ambient (DALC) cube: the cube stores irradiance, as the
// raster path that reads it knows, and the radiance along the escaping ray is
// that irradiance over pi (the uniform environment that would produce it).
space world;

uniform samplerCube<spectrum<irradiance>, world> dalcCube;
uniform samplerCube<spectrum<radiance>, world> skyCube;
uniform bool useDalc;

flat in direction<world> rayDir;
flat in spectrum<1> throughput;
out vec4 fragColor;

const float PI = 3.14159265358979;

spectrum<irradiance> sampleDalcCube(direction<world> dir) {
    return texture(dalcCube, dir).rgb;
}

spectrum<radiance> pathEnvironmentRadiance(direction<world> dir) {
    if (useDalc) {
        return sampleDalcCube(dir) * (1.0 / PI);
    }
    return texture(skyCube, dir).rgb;
}

void main() {
    spectrum<radiance> L = throughput * pathEnvironmentRadiance(rayDir);
    fragColor = vec4(L, 1.0);
}
