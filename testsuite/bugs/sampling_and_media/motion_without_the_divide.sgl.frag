#version 330 core
#include <safegi/prelude.sgl>
// Shapes from outside programs: a sphere light sampled by its cone of
// directions, an area light sampled by area (the Jacobian to solid angle),
// single scattering in fog with a Henyey-Greenstein phase function, a
// directional shadow map and TAA motion vectors.
space world;
space clip;
space prev_clip;
space light_clip;

uniform point<world> sphereCenter;
uniform float<length> sphereRadius;
uniform spectrum<radiance> sphereLe;
uniform point<world> areaSample;                       // drawn uniformly on the area light
uniform normal<world> areaNormal;
uniform float<area> areaSize;
uniform spectrum<radiance> areaLe;
uniform spectrum<brdf> Kd;
uniform point<world> eyePos;
uniform float<inv_length> sigmaS;                      // scattering coefficient of the fog
uniform float<1> g;                                    // Henyey-Greenstein asymmetry
uniform float<length> fogDepth;
uniform projmap<world, clip> clipFromWorld;
uniform projmap<world, prev_clip> prevClipFromWorld;
uniform projmap<world, light_clip> lightClipFromWorld;
uniform sampler2D<float<1>> shadowDepth;               // window-space depth in [0, 1]

in point<world> P;
in normal<world> Ng;
out vec4 fragColor;
out vec2 motion;

const float<1> PI = 3.14159265358979;

void main() {
    normal<world> n = normalize(Ng);
    direction<world> wo = normalize(eyePos - P);

    // Sphere light, uniform in its cone: pdf = 1 / (2π (1 - cos θmax)) per steradian.
    vector<world> toC = sphereCenter - P;
    float<length> dC = length(toC);
    direction<world> wc = normalize(toC);
    float<1> sinMax = sphereRadius / dC;
    float<1> cosMax = sqrt(max(1.0 - sinMax * sinMax, 0.0));
    float<solid_angle> cone = 2.0 * PI * (1.0 - cosMax) * steradian;
    float<pdf_solid_angle> pdfCone = 1.0 / cone;
    float<proj> cosS = max(dot(n, wc), 0.0);
    spectrum<radiance> Lsphere = Kd * sphereLe * cosS / pdfCone;

    // Area light sampled by area: dω = cos θy dA / r².
    vector<world> toY = areaSample - P;
    float<length> r = length(toY);
    direction<world> wy = normalize(toY);
    float<proj> cosY = max(dot(areaNormal, -wy), 0.0);
    float<solid_angle / (area * proj)> invR2 = float<solid_angle / (area * proj)>(1.0 / (r * r));
    float<pdf_solid_angle> pdfY = 1.0 / (areaSize * cosY * invR2);
    float<proj> cosA = max(dot(n, wy), 0.0);
    spectrum<radiance> Larea = Kd * areaLe * cosA / pdfY;

    // Fog: light from the sphere scattered toward the eye, HG phase per steradian.
    float<1> cosPhase = dot(wc, -wo);
    float<1> hg = 1.0 + g * g - 2.0 * g * cosPhase;
    float<pdf_solid_angle> phase = (1.0 - g * g) / (4.0 * PI * steradian * hg * sqrt(hg));
    spectrum<radiance> Lfog = sigmaS * fogDepth * phase * sphereLe / pdfCone;

    // Directional shadow map: depths compare after the divide by w.
    hpoint<light_clip> hL = lightClipFromWorld * P;
    vec3 ndcL = hL.xyz / hL.w;
    float<1> stored = texture(shadowDepth, ndcL.xy * 0.5 + 0.5).r;
    float currentDepth = ndcL.z * 0.5 + 0.5;
    float lit = currentDepth - 0.005 > stored ? 0.0 : 1.0;

    // TAA: this frame's and last frame's screen positions, each after its own divide.
    hpoint<clip> hNow = clipFromWorld * P;
    hpoint<prev_clip> hPrev = prevClipFromWorld * P;
    motion = hNow.xy - hPrev.xy;

    fragColor = vec4((Lsphere + Larea) * lit + Lfog, 1.0);
}
