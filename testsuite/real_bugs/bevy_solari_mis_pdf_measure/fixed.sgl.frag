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
flat in normal<world> hitNormal;                   // the emitter's normal at the hit (not interpolated)
in point<world> previousPosition;                   // where the ray started
in float<pdf_solid_angle> brdfPdf;                  // the BRDF sample's pdf
out vec4 radianceOut;

void main() {
    vec3 d = hitPosition - previousPosition;
    float rayDistance = length(d);
    vec3 wi = normalize(d);
    float cosLight = abs(dot(hitNormal, wi));
    float lightPdfArea = lightSelectionPdf * inverseLightArea;
    float lightPdf = float<pdf_solid_angle>(lightPdfArea * rayDistance * rayDistance / cosLight);
    float misWeight = brdfPdf / (brdfPdf + lightPdf);
    spectrum<radiance> radiance = misWeight * throughput * emissive;
    radianceOut = vec4(radiance, 1.0);
}
