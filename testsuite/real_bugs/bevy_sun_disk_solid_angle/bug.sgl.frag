#version 330 core
#include <safegi/prelude.sgl>
// An atmosphere's sun disk: the sun's radiance is its illuminance spread over
// the disk's solid angle, pi r^2 for an angular radius r, that is
// pi d^2 / 4 for the angular diameter d (small-angle approximation).
space world;

uniform float<angle> sunAngularSize;                 // angular diameter, about 0.0093 rad
uniform spectrum<irradiance / proj> sunIlluminance;  // on a surface facing the sun
uniform direction<world> sunDirection;
uniform spectrum<radiance> skyRadiance;

in direction<world> rayDir;
out vec4 fragColor;

const float PI = 3.141592653589793;

void main() {
    float sunSolidAngle = float<solid_angle>(sunAngularSize * sunAngularSize * 4.0 / PI);
    spectrum<radiance> sunRadiance = sunIlluminance / sunSolidAngle;
    float cosToSun = dot(rayDir, sunDirection);
    bool inDisk = cosToSun > cos(sunAngularSize * 0.5);
    fragColor = vec4(inDisk ? sunRadiance : skyRadiance, 1.0);
}
