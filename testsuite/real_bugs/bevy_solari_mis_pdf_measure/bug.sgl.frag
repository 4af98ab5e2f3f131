#version 330 core
#include <safegi/prelude.sgl>
// A real-time path tracer's hit on an emissive triangle that the BRDF ray
// found: its emission is weighted by the balance heuristic against the pdf
// with which light sampling (next-event estimation) would have picked the
// same direction. Both pdfs must be per solid angle.
space world;

uniform float<inv_area> inverseLightArea;          // uniform point on the emitter: pdf per area
uniform float<1> lightSelectionPdf;                // chance of picking this emitter
uniform spectrum<radiance> emissive;
uniform spectrum<1> throughput;

in point<world> hitPosition;                        // the emitter point the ray hit
in normal<world> hitNormal;
in point<world> previousPosition;                   // where the ray started
in float<pdf_solid_angle> brdfPdf;                  // the BRDF sample's pdf
out vec4 radianceOut;

void main() {
    vector<world> d = hitPosition - previousPosition;
    float<length> rayDistance = length(d);
    direction<world> wi = normalize(d);
    float<proj> cosLight = abs(dot(hitNormal, wi));
    float<pdf_area> lightPdfArea = lightSelectionPdf * inverseLightArea;
    float<pdf_solid_angle> lightPdf = float<pdf_solid_angle>(lightPdfArea * rayDistance * rayDistance / cosLight);
    float<1> misWeight = brdfPdf / (brdfPdf + lightPdfArea);
    spectrum<radiance> radiance = misWeight * throughput * emissive;
    radianceOut = vec4(radiance, 1.0);
}
