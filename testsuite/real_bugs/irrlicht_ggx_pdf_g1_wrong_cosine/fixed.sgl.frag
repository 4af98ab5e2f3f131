#version 330 core
#include <safegi/prelude.sgl>
// An engine's GGX sampler of visible normals: the pdf of the reflected
// direction is D(h) G1(v) / (4 N.V); the masking term G1 is the view's,
// evaluated at N.V, not the light's.
space world;

uniform float<1> a2;                                  // alpha squared
uniform spectrum<radiance> Li;
uniform spectrum<1> F0;

in direction<world, away> V;
in direction<world, away> L;                          // the sampled direction
flat in normal<world> N;                               // the shading normal, given (not interpolated)
out vec4 fragColor;

const float PI = 3.141592653589793;

float GGXSmith_G1(float NdotX, float a2) {
    return 2.0 * NdotX / (NdotX + sqrt(a2 + (1.0 - a2) * NdotX * NdotX));
}

void main() {
    vec3 H = normalize(V + L);
    float NdotV = abs(dot(N, V)) + 1e-5;
    float NdotL = abs(dot(N, L)) + 1e-5;
    float NdotH = max(dot(N, H), 0.0);
    float t = NdotH * NdotH * (a2 - 1.0) + 1.0;
    float D = a2 / (PI * t * t);
    float G1 = GGXSmith_G1(NdotV, a2);
    float pdf = float<pdf_solid_angle>(D * G1 / (4.0 * NdotV));
    float G2 = GGXSmith_G1(NdotV, a2) * GGXSmith_G1(NdotL, a2);
    float f_cos = float<pdf_solid_angle>(D * G2 / (4.0 * NdotV));
    spectrum<radiance> L_o = F0 * Li * f_cos / pdf;
    fragColor = vec4(L_o, 1.0);
}
