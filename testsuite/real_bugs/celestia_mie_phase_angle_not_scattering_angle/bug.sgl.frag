#version 330 core
#include <safegi/prelude.sgl>
// A planetarium's atmosphere shell: sunlight scattered once toward the eye,
// weighted by a Rayleigh phase function and a Schlick approximation of the
// Mie phase function. Both take the cosine of the scattering angle, between
// the direction the sunlight travels and the direction it leaves toward the
// eye; the angle at the point between the sun and the eye (the phase angle)
// is its supplement.
space world;

uniform direction<world, away> sunDirection;      // from the atmosphere toward the sun
uniform point<world> eyePos;
uniform float<1> mieAsymmetry;                    // Schlick k: > 0 scatters forward
uniform spectrum<irradiance> sunIrradiance;
uniform spectrum<inv_length> rayleighCoeff;
uniform spectrum<inv_length> mieCoeff;

in point<world, shaded> P;
in float<length> pathLength;                      // length of the ray segment in the shell
out vec4 fragColor;

float<pdf_solid_angle> rayleighPhase(float cosTheta) {
    return 3.0 / (16.0 * 3.14159265) * (1.0 + cosTheta * cosTheta);
}

float<pdf_solid_angle> schlickPhase(float<1> k, float cosTheta) {
    float d = 1.0 + k * cosTheta;
    return (1.0 - k * k) / (4.0 * 3.14159265 * d * d);
}

void main() {
    direction<world, away> toEye = normalize(eyePos - P);
    float cosTheta = dot(sunDirection, toEye);
    spectrum<radiance> L = sunIrradiance * pathLength
        * (rayleighCoeff * rayleighPhase(cosTheta) + mieCoeff * schlickPhase(mieAsymmetry, cosTheta));
    fragColor = vec4(L, 1.0);
}
