#version 330 core
#include <safegi/prelude.sgl>
// A physically based sky: the atmosphere is described in kilometres (planet
// radius, scale heights), the scene in metres, so the camera's altitude is
// converted before it enters the exponential density profiles.
space world;

uniform point<world> cameraPosition;
uniform point<world> planetCenter;
uniform float<length in kilometer> planetRadius;
uniform float<length in kilometer> rayleighScaleHeight;   // about 8 km
uniform float<length in kilometer> mieScaleHeight;        // about 1.2 km
uniform spectrum<radiance> skyTint;

in direction<world> viewDirection;
out vec4 fragColor;

float<1> densityRayleigh(float<length in kilometer> altitude) { return exp(-altitude / rayleighScaleHeight); }
float<1> densityMie(float<length in kilometer> altitude) { return exp(-altitude / mieScaleHeight); }

void main() {
    float r = length(cameraPosition - planetCenter) in kilometer;
    float altitude = max(r - planetRadius, 0.0);
    float rayleigh = densityRayleigh(altitude);
    float mie = densityMie(altitude);
    float<1> upness = 0.5 + 0.5 * viewDirection.y;
    fragColor = vec4(skyTint * (rayleigh * upness + 0.1 * mie), 1.0);
}
