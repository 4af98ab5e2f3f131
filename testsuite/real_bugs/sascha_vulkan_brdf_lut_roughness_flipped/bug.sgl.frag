#version 450
#include <safegi/prelude.sgl>
// Vulkan PBR example: precomputes the split-sum BRDF table (scale and bias of
// F0) by importance-sampling the GGX lobe; u indexes the cosine NdotV, v the
// roughness. The full-screen pass's v already runs along the table's rows the
// way the lighting pass looks them up, so the roughness is v itself.
layout(location = 0) in vec2 inUV;
layout(location = 0) out vec4 outColor;

const uint SAMPLE_COUNT = 1024u;

vec2 hammersley(uint i, uint n) {
    uint bits = bitfieldReverse(i);
    return vec2(float(i) / float(n), float(bits) * 2.3283064365386963e-10);
}

vec3 sampleGGXHalfVector(vec2 xi, float roughness) {
    float a = roughness * roughness;
    float phi = 6.283185307179586 * xi.x;
    float cosTheta = sqrt((1.0 - xi.y) / (1.0 + (a * a - 1.0) * xi.y));
    float sinTheta = sqrt(1.0 - cosTheta * cosTheta);
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

float smithGGX(float NdotL, float NdotV, float roughness) {
    float k = roughness * roughness / 2.0;
    float gl = NdotL / (NdotL * (1.0 - k) + k);
    float gv = NdotV / (NdotV * (1.0 - k) + k);
    return gl * gv;
}

vec2 integrateBRDF(float<proj> NdotV, float<1> roughness) {
    vec3 V = vec3(sqrt(1.0 - NdotV * NdotV), 0.0, NdotV);
    vec2 sum = vec2(0.0);
    for (uint i = 0u; i < SAMPLE_COUNT; i++) {
        vec3 H = sampleGGXHalfVector(hammersley(i, SAMPLE_COUNT), roughness);
        vec3 L = 2.0 * dot(V, H) * H - V;
        float NdotL = max(L.z, 0.0);
        float NdotH = max(H.z, 0.0);
        float VdotH = max(dot(V, H), 0.0);
        if (NdotL > 0.0) {
            float G = smithGGX(NdotL, NdotV, roughness);
            float Gvis = G * VdotH / (NdotH * NdotV);
            float Fc = pow(1.0 - VdotH, 5.0);
            sum += vec2((1.0 - Fc) * Gvis, Fc * Gvis);
        }
    }
    return sum / float(SAMPLE_COUNT);
}

void main() {
    outColor = vec4(integrateBRDF(inUV.s, 1.0 - inUV.t), 0.0, 1.0);
}
