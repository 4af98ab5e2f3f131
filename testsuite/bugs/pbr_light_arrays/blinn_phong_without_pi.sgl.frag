#version 330 core
#include <safegi/prelude.sgl>
// LearnOpenGL-style PBR as an outside user writes it: four point lights and a
// spot light, Lambert plus GGX, a Blinn-Phong highlight for the spot, a
// normal map through the TBN basis, the spot's cone in degrees and its reach
// in centimetres, user generic helpers.
space world;
space tangent;

const int NUM_LIGHTS = 4;
uniform point<world> lightPositions[NUM_LIGHTS];
uniform spectrum<intensity> lightIntensities[NUM_LIGHTS];
uniform point<world> camPos;
uniform spectrum<1> albedo;
uniform float<1> roughness;
uniform float<1> metallic;
uniform sampler2D normalMap;
uniform rigidmap<tangent, world> worldFromTangent;     // the TBN basis
uniform point<world> spotPos;
uniform direction<world> spotAxis;
uniform spectrum<intensity> spotI;
uniform float<angle in degree> innerConeDeg;
uniform float<angle in degree> outerConeDeg;
uniform float<length in centimeter> spotReachCm;
uniform float<1> shininess;

in point<world, shaded> WorldPos;              // the point being shaded
in vec2 TexCoords;
out vec4 FragColor;

const float<1> PI = 3.14159265359;
const float<brdf> INV_PI = float<brdf>(0.318309886);   // 1/π per projected steradian

template<space S>
float<proj> cosineTo(normal<S> n, direction<S> w) { return max(dot(n, w), 0.0); }

template<dimension D>
float<D> saturateTo(float<D> x, float<D> top) { return clamp(x, 0.0 * top, top); }

float<1> smithG1(float<1> c, float<1> k) { return c / (c * (1.0 - k) + k); }

void main() {
    normal<tangent> nT = normal<tangent>(texture(normalMap, TexCoords).rgb * 2.0 - 1.0);
    normal<world> N = normalize(worldFromTangent * nT);
    direction<world, away> V = normalize(camPos - WorldPos);
    float<1> NdotV = max(dot(N, V), 0.0);               // a cosine used as a number
    direction<world> R = normalize(2.0 * dot(N, V) * N - V);
    spectrum<1> F0 = mix(vec3(0.04), albedo, metallic);
    float<1> a = roughness * roughness;
    float<1> k = (roughness + 1.0) * (roughness + 1.0) / 8.0;

    spectrum<radiance> Lo = spectrum<radiance>(0.0);
    for (int i = 0; i < NUM_LIGHTS; ++i) {
        vector<world, away> toL = lightPositions[i] - WorldPos;
        float<length> d = length(toL);
        direction<world, away> L = normalize(toL);
        direction<world> H = normalize(V + L);
        float<proj> cosL = cosineTo(N, L);
        float<1> NdotL = cosL;
        float<1> NdotH = max(dot(N, H), 0.0);
        float<1> denom = NdotH * NdotH * (a * a - 1.0) + 1.0;
        float<brdf> D = a * a * INV_PI / (denom * denom);
        float<1> G = smithG1(NdotV, k) * smithG1(NdotL, k);
        spectrum<1> F = F0 + (1.0 - F0) * pow(1.0 - max(dot(H, V), 0.0), 5.0);
        spectrum<brdf> specular = D * G * F / (4.0 * NdotV * NdotL + 0.0001);
        spectrum<1> kD = (vec3(1.0) - F) * (1.0 - metallic);
        float<solid_angle / (area * proj)> falloff = float<solid_angle / (area * proj)>(1.0 / (d * d));
        spectrum<irradiance> E = lightIntensities[i] * falloff * cosL;
        Lo += (kD * albedo * INV_PI + specular) * E;
    }

    // The spot light: a smooth cone between the inner and outer angles.
    vector<world, away> toS = spotPos - WorldPos;
    float<length> ds = length(toS);
    direction<world, away> Ls = normalize(toS);
    float<1> cosInner = cos(radians(innerConeDeg));
    float<1> cosOuter = cos(outerConeDeg in radian);
    float<1> cone = clamp((dot(-Ls, spotAxis) - cosOuter) / (cosInner - cosOuter), 0.0, 1.0);
    float<length> reach = spotReachCm in meter;
    float<1> fade = saturateTo(1.0 - ds / reach, 1.0);
    direction<world> Hs = normalize(V + Ls);
    float blinn = (shininess + 8.0) / 8.0 * pow(max(dot(N, Hs), 0.0), shininess);
    float<solid_angle / (area * proj)> falloffS = float<solid_angle / (area * proj)>(1.0 / (ds * ds));
    spectrum<irradiance> Es = spotI * falloffS * cosineTo(N, Ls) * cone * fade;
    spectrum<radiance> Lspot = albedo * blinn * Es;

    float<1> mirror = max(dot(R, V), 0.0);               // the written-out reflection is a direction
    FragColor = vec4(Lo + Lspot, mirror);
}
