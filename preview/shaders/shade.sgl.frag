#version 330 core
// Direct illumination, one light per pass, added into a float accumulation
// buffer. Built four times (docs/preview.md):
//   EMISSION      emitters seen directly (the pass that also lays down depth);
//   POINT_LIGHT   a point or spot light of intensity I (times the spot's
//                 falloff): L = f · I · cos θx / r²;
//   AREA_SAMPLE   one of N points y on an emitter of area A and radiance Le,
//                 a point-like light of intensity Le · cos θy · A / N;
//   MIRROR        a planar mirror, one bounce: Kr times the radiance its
//                 reflection pass found at this pixel.
// The BRDFs are the CPU renderer's (cpu_renderer/src/materials/bsdf.hpp): Lambert ρ/π
// and energy-conserving Phong ρs (n+2)/(2π) cosⁿα, two-sided.
#include <safegi/prelude.sgl>

space world;
space light_clip;

uniform point<world> eye;

in point<world>  P;
in normal<world> N;

out spectrum<radiance> radiance;

#if defined(MIRROR)
uniform spectrum<1>                   Kr;
uniform sampler2D<spectrum<radiance>> reflection;  // the scene through this mirror, same pixels

void main() {
    spectrum<radiance> seen = spectrum<radiance>(texelFetch(reflection, ivec2(gl_FragCoord.xy), 0).rgb);
    radiance = Kr * seen;
}
#elif defined(EMISSION)
uniform spectrum<radiance> Le;
uniform int                emitterTwoSided;

void main() {
    direction<world> wo = normalize(eye - P);
    float<proj> facing = dot(normalize(N), wo);
    bool emits = facing > 0.0 || emitterTwoSided != 0;
    radiance = emits ? Le : spectrum<radiance>(0.0);
}
#else
const float INV_PI = 0.3183098861837907;

uniform spectrum<1> Kd;                      // Lambert albedo, Phong diffuse part
uniform spectrum<1> Ks;                      // Phong specular part
uniform float       phongExponent;

uniform point<world> lightPosition;
#ifdef AREA_SAMPLE
uniform spectrum<radiance> Le;
uniform float<area>        sampleArea;       // A / N: the emitter's area per sample
uniform normal<world>      emitterNormal;
uniform int                emitterTwoSided;
#else
uniform spectrum<intensity> lightIntensity;
// A spot light's cone (pbrt-v3's): full intensity up to cos θ = spotCosStart,
// then δ⁴ down to spotCosTotal, nothing beyond. A point light: both -2.
uniform direction<world>    spotAxis;
uniform float               spotCosTotal;
uniform float               spotCosStart;

float<1> spotFalloff(direction<world> fromLight) {
    float<1> c = dot(spotAxis, fromLight);
    if (c < spotCosTotal) return 0.0;
    if (c >= spotCosStart) return 1.0;
    float<1> d = (c - spotCosTotal) / (spotCosStart - spotCosTotal);
    return (d * d) * (d * d);
}
#endif

// Visibility from a cube shadow map laid out as 3 x 2 faces in one texture of
// distances (face f at column f % 3, row f / 3).
uniform sampler2D<float<length>>   shadowMap;
uniform projmap<world, light_clip> shadowClipFromWorld[6];
uniform float                      shadowFaceTexels;
uniform float                      shadowBiasTexels;

float<1> visibility(vector<world> fromLight, float<1> tanTheta) {
    float<length> ax = abs(fromLight.x);
    float<length> ay = abs(fromLight.y);
    float<length> az = abs(fromLight.z);
    int face = 4;
    if (ax >= ay && ax >= az) face = fromLight.x > 0.0 ? 0 : 1;
    else if (ay >= az) face = fromLight.y > 0.0 ? 2 : 3;
    else face = fromLight.z > 0.0 ? 4 : 5;
    hpoint<light_clip> h = shadowClipFromWorld[face] * P;
    point<light_clip> ndc = homogenize(h);
    float halfTexel = 0.5 / shadowFaceTexels;
    vec2 inFace = clamp(ndc.xy / meter * 0.5 + 0.5, vec2(halfTexel), vec2(1.0 - halfTexel));
    vec2 uv = (inFace + vec2(float(face % 3), float(face / 3))) / vec2(3.0, 2.0);
    float<length> stored = texture(shadowMap, uv).r;
    float<length> dist = length(fromLight);
    // A texel spans about 2/S radians, so the stored distance is off by up to
    // dist · (2/S) · tan θ on a surface tilted by θ to the light.
    float<length> bias = dist * (2.0 / shadowFaceTexels) * shadowBiasTexels * (1.0 + min(tanTheta, 8.0));
    return dist - bias > stored ? 0.0 : 1.0;
}

void main() {
    direction<world> wo = normalize(eye - P);
    normal<world> n = normalize(N);
    if (dot(n, wo) < 0.0) n = -n;            // materials are two-sided
    vector<world> toLight = lightPosition - P;
    float<length> r = length(toLight);
    direction<world> wi = normalize(toLight);
    float<proj> cosX = dot(n, wi);
    if (cosX <= 0.0) discard;

#ifdef AREA_SAMPLE
    float<proj> cosY = -dot(normalize(emitterNormal), wi);
    if (emitterTwoSided != 0) cosY = abs(cosY);
    if (cosY <= 0.0) discard;
    spectrum<intensity> I = Le * cosY * sampleArea;
#else
    spectrum<intensity> I = lightIntensity * spotFalloff(-wi);
#endif

    float<1> cosAlpha = max(2.0 * dot(n, wo) * cosX - dot(wo, wi), 0.0);
    spectrum<1> albedoTerms = Kd * INV_PI + Ks * ((phongExponent + 2.0) * 0.5 * INV_PI * pow(cosAlpha, phongExponent));
    spectrum<brdf> f = spectrum<brdf>(albedoTerms);
    // cos θx / r²: the solid angle the light sees per unit of receiving area.
    float<solid_angle / area> G = float<solid_angle / area>(cosX / (r * r));
    float<1> cosXPlain = cosX;
    float<1> tanTheta = sqrt(max(1.0 - cosXPlain * cosXPlain, 0.0)) / max(cosXPlain, 0.05);
    radiance = f * I * G * visibility(P - lightPosition, tanTheta);
}
#endif
