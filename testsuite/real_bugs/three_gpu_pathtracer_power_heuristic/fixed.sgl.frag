#version 300 es
#include <safegi/prelude.sgl>
// A path tracer's next-event estimate for an area light, weighted by
// multiple importance sampling against BSDF sampling with the power
// heuristic w = a^2 / (a^2 + b^2), both pdfs per solid angle.
precision highp float;
space world;

uniform spectrum<radiance> lightRadiance;
uniform float<pdf_solid_angle> lightPdf;              // of the light sample, converted to solid angle
uniform float<pdf_solid_angle> bsdfPdf;               // of the same direction under BSDF sampling
uniform spectrum<brdf> bsdfValue;

in normal<world> vNormal;
in direction<world> vLightDir;                        // toward the light sample
out vec4 fragColor;

float misHeuristic(float<pdf_solid_angle> a, float<pdf_solid_angle> b) {
    float aa = a * a;
    float bb = b * b;
    return aa / (aa + bb);
}

void main() {
    float cosTheta = max(dot(normalize(vNormal), vLightDir), 0.0);
    float weight = misHeuristic(lightPdf, bsdfPdf);
    spectrum<radiance> L = bsdfValue * lightRadiance * cosTheta * weight / lightPdf;
    fragColor = vec4(L, 1.0);
}
