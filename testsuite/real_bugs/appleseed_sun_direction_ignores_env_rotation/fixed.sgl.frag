#version 450
#include <safegi/prelude.sgl>
// A renderer's sun light tied to a sky environment: the sun's position is
// given by zenith and azimuth angles in the environment's frame (y up); the
// environment can be rotated in the scene, so the direction goes through the
// environment's transform before lighting.
space env;
space world;

uniform mat3<env, world, rigid> envToWorld;
uniform float<angle> sunTheta;    // zenith angle
uniform float<angle> sunPhi;      // azimuth
uniform spectrum<irradiance / proj> sunIrradiance;
uniform spectrum<brdf> albedo;

in normal<world> worldNormal;
out vec4 fragColor;

direction<env> sunDirectionEnv(float<angle> theta, float<angle> phi) {
    return vec3(sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi));
}

void main() {
    vec3 sunDir = envToWorld * sunDirectionEnv(sunTheta, sunPhi);
    float cosL = max(dot(normalize(worldNormal), sunDir), 0.0);
    fragColor = vec4(albedo * sunIrradiance * cosL, 1.0);
}
