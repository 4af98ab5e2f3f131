#version 450
#include <safegi/prelude.sgl>
// A renderer's Henyey-Greenstein phase function sampling (C++ in the
// original): the cosine of the scattering angle is drawn from the HG inverse
// CDF, with the uniform-sphere fallback only where g is too close to zero for
// the formula (|g| < eps); a negative g scatters backward and needs the
// formula as much as a positive one.
const float EPS = 1e-5;

uniform float<1> g;                 // asymmetry in (-1, 1)
in vec2 u;                          // two uniform random numbers
out vec4 sampledDirectionPdf;

float<pdf_solid_angle> hgPdf(float<1> g, float cosTheta) {
    float denom = 1.0 + g * g - 2.0 * g * cosTheta;
    return (1.0 - g * g) / (4.0 * 3.14159265 * denom * sqrt(denom));
}

void main() {
    float cosTheta;
    if (g < EPS) {
        cosTheta = 1.0 - 2.0 * u.x;
    } else {
        float sqrTerm = (1.0 - g * g) / (1.0 - g + 2.0 * g * u.x);
        cosTheta = (1.0 + g * g - sqrTerm * sqrTerm) / (2.0 * g);
    }
    float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
    float phi = 6.283185307179586 * u.y;
    vec3 w = vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
    sampledDirectionPdf = vec4(w, hgPdf(g, cosTheta));
}
