#version 450
#include <safegi/prelude.sgl>
// Next-event estimation with a measured BRDF: the table is parameterised
// asymmetrically (it is indexed by the outgoing direction first, the way the
// sampling routine draws the incident one from it), so evaluating f for a
// light sample must pass (wo, wi) in the order sampling uses.
space shading : frame;                  // the shading frame: z is the normal

uniform sampler2D measuredTable;                      // rows: outgoing elevation, columns: half-vector elevation
uniform spectrum<brdf> tableScale;
uniform spectrum<radiance> lightRadiance;
uniform float<pdf_solid_angle> lightPdf;

in direction<shading> wo;                             // toward the viewer
in direction<shading> wi;                             // toward the light sample
out vec4 fragColor;

spectrum<brdf> measuredF(direction<shading> o, direction<shading> i) {
    vec3 h = normalize(o + i);
    return tableScale * texture(measuredTable, vec2(o.z, h.z)).rgb;
}

void main() {
    float cosI = max(wi.z, 0.0);
    spectrum<radiance> L = measuredF(wo, wi) * lightRadiance * cosI / lightPdf;
    fragColor = vec4(L, 1.0);
}
