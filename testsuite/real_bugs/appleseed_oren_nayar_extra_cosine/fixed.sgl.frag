#version 330 core
#include <safegi/prelude.sgl>
// Oren-Nayar diffuse as a BRDF evaluated for one point light; the caller
// multiplies by the cosine at the receiver, so the BRDF value has none.
space world;

uniform point<world> lightPos;
uniform spectrum<intensity> lightI;
uniform point<world> eyePos;
uniform spectrum<1> reflectance;
uniform float<1> sigma;                         // roughness, standard deviation of slopes

in point<world, shaded> P;
in normal<world> Nin;
out vec4 fragColor;

const float<brdf> RcpPi = float<brdf>(0.31830988618);

spectrum<brdf> orenNayar(normal<world> n, direction<world> wo, direction<world> wi) {
    float cosIn = max(dot(n, wi), 0.0);
    float cosOut = max(dot(n, wo), 0.0);
    float sigma2 = sigma * sigma;
    float A = 1.0 - 0.5 * sigma2 / (sigma2 + 0.33);
    float B = 0.45 * sigma2 / (sigma2 + 0.09);
    vec3 projIn = wi - cosIn * n;
    vec3 projOut = wo - cosOut * n;
    float cosPhi = max(dot(normalize(projIn), normalize(projOut)), 0.0);
    float sinAlpha = sqrt(1.0 - min(cosIn, cosOut) * min(cosIn, cosOut));
    float tanBeta = sqrt(1.0 - max(cosIn, cosOut) * max(cosIn, cosOut)) / (max(cosIn, cosOut) + 1e-4);
    return reflectance * RcpPi * (A + B * cosPhi * sinAlpha * tanBeta);
}

void main() {
    vec3 n = normalize(Nin);
    vec3 wo = normalize(eyePos - P);
    vec3 toLight = lightPos - P;
    float d = length(toLight);
    vec3 wi = normalize(toLight);
    float cosTheta = max(dot(n, wi), 0.0);
    float falloff = float<solid_angle / (area * proj)>(1.0 / (d * d));
    spectrum<radiance> L = orenNayar(n, wo, wi) * lightI * falloff * cosTheta;
    fragColor = vec4(L, 1.0);
}
