#version 330 core
#include <safegi/prelude.sgl>
// In a frame whose z axis is the normal (pbrt's shading space), a unit
// direction's z is its cosine to the normal: CosTheta(w) = w.z. A vector's z
// is a length, and outside such a frame z is a plain coordinate.
space world;
space shading : frame;
uniform spectrum<radiance> Li;
uniform spectrum<brdf> f;
uniform float<pdf_solid_angle> pdf;
uniform direction<shading> wi;
uniform vector<shading> offset;
uniform direction<world> wiWorld;
out vec4 c;
void main() {
    float cosI = max(wi.z, 0.0);
    spectrum<radiance> L = f * Li * cosI / pdf;
    float<length> height = offset.z;
    spectrum<radiance> wrong = f * Li * max(wiWorld.z, 0.0) / pdf;
    c = vec4(L + wrong, height / meter);
}
