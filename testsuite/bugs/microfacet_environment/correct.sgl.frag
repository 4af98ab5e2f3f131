#version 330 core
#include <safegi/prelude.sgl>
// Image-based lighting with a GGX lobe: one environment sample drawn by the
// GGX density of micro-normals, weighted by the Cook-Torrance BRDF over its pdf.
space world;
space tangent;                                         // z along the surface normal

uniform samplerCube<spectrum<radiance>> environment;
uniform rigidmap<tangent, world> worldFromTangent;
uniform point<world> eyePos;
uniform float<1> alpha;                                // GGX roughness
uniform spectrum<1> F0;                                // Fresnel reflectance at normal incidence
uniform vec2<1> xi;                                    // two uniform random numbers

in point<world, shaded> P;
in normal<world> N;
out vec4 fragColor;

const float<1> PI = 3.14159265358979;

// Smith's masking for one direction, from its cosine to the normal.
float<1> smithG1(float<1> c, float<1> a2) { return 2.0 * c / (c + sqrt(a2 + (1.0 - a2) * c * c)); }

void main() {
    normal<world> n = normalize(N);
    direction<world, away> wo = normalize(eyePos - P);
    float<proj> cosO = max(dot(n, wo), 0.0);
    // A micro-normal h from the GGX distribution D (∫ D cos θh dω = 1).
    float<1> a2 = alpha * alpha;
    float<1> cosH2 = (1.0 - xi.x) / (1.0 + (a2 - 1.0) * xi.x);
    float<1> cosH = sqrt(cosH2);
    float<1> sinH = sqrt(1.0 - cosH2);
    float<angle> phi = 2.0 * PI * xi.y * radian;
    normal<tangent> hT = normal<tangent>(vec3(sinH * cos(phi), sinH * sin(phi), cosH));
    normal<world> h = worldFromTangent * hT;
    direction<world, away> wi = reflect(-wo, h);
    float<proj> cosI = max(dot(n, wi), 0.0);
    float<1> t = cosH2 * (a2 - 1.0) + 1.0;
    float<pdf_projected_solid_angle> D = float<pdf_projected_solid_angle>(a2 / (PI * t * t));
    // pdf of h per solid angle is D·cos θh; the reflection's Jacobian dωh/dωi is 1/(4 wo·h).
    float<1> oDotH = dot(wo, h);
    float<pdf_solid_angle> pdfH = D * float<proj>(cosH);
    float<pdf_solid_angle> pdfWi = pdfH / (4.0 * oDotH);
    // Cook-Torrance: D F G / (4 cos θi cos θo); the cosines here normalise, they do not project.
    spectrum<1> F = F0 + (1.0 - F0) * pow(1.0 - oDotH, 5);
    float<1> G = smithG1(cosI, a2) * smithG1(cosO, a2);
    spectrum<brdf> fr = F * G * D / (4.0 * cosI * cosO + 1e-4);
    spectrum<radiance> Li = spectrum<radiance>(texture(environment, wi).rgb);
    spectrum<radiance> L = fr * Li * cosI / pdfWi;
    fragColor = vec4(L, 1.0);
}
