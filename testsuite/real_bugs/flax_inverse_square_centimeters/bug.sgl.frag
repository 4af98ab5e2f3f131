#version 330 core
#include <safegi/prelude.sgl>
// An engine whose world unit is the centimetre: a light's inverse-square
// falloff is defined per square metre, so the squared distance in cm^2 is
// converted to m^2 before it divides the intensity.
space world;

uniform spectrum<intensity> lightIntensity;
uniform spectrum<brdf> diffuseColor;

in vector<world, length in centimeter, away> toLightCm;   // from the shaded point, in world units (cm)
in normal<world> worldNormal;
out vec4 fragColor;

void main() {
    float distanceSqrCm = dot(toLightCm, toLightCm);
    float distanceSqr = distanceSqrCm;
    vec3 L = normalize(toLightCm);
    float NoL = max(dot(normalize(worldNormal), L), 0.0);
    float attenuation = float<solid_angle / (area * proj)>(1.0 / max(distanceSqr, 0.0001 * square_meter));
    spectrum<radiance> color = diffuseColor * lightIntensity * attenuation * NoL;
    fragColor = vec4(color, 1.0);
}
