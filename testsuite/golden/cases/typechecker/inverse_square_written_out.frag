#version 330 core
#include <safegi/prelude.sgl>
// The inverse-square law written out: a value divided by a squared distance
// (d * d of a length, in a product or through a local) may be the solid angle
// per projected area that inverse_square(d) is, and is read so where it is
// stored when that makes it fit; a squared distance in the numerator (a pdf
// converted from area to solid angle) the other way. A missing cosine, or an
// intensity taken for radiance, still does not fit.
space world;
uniform spectrum<intensity> I;
uniform point<world> lightPos;
uniform float<pdf_area> pdfA;
in point<world, shaded> P;
in normal<world> N;
out vec4 c;
void main() {
    vec3 toLight = lightPos - P;
    float dist = length(toLight);
    float cosTheta = max(dot(normalize(N), toLight / dist), 0.0);
    spectrum<irradiance> E = I * cosTheta / (dist * dist);
    float g = cosTheta / (dist * dist);
    spectrum<irradiance> E2 = I * g;
    float<pdf_solid_angle> pdfW = pdfA * dist * dist / cosTheta;
    spectrum<irradiance> missingCosine = I / (dist * dist);
    spectrum<radiance> intensityAsRadiance = I * cosTheta / (dist * dist);
    c = vec4(E + E2 + missingCosine, pdfW);
}
