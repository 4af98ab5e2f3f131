#version 330 core
#include <safegi/prelude.sgl>
// A renderer's direct lighting with several samples per light: each sample
// is a full estimate f * Le * cos / pdf, so their sum is divided by the
// number of samples.
space world;

const int MAX_SAMPLES = 16;
uniform int lightSampleCount;
uniform point<world> lightSamples[MAX_SAMPLES];        // drawn uniformly on the emitter
uniform normal<world> lightNormal;
uniform float<area> lightArea;
uniform spectrum<radiance> Le;
uniform spectrum<brdf> bsdf;

in point<world, shaded> P;
in normal<world> N;
out vec4 fragColor;

void main() {
    vec3 n = normalize(N);
    vec3 sum = spectrum<radiance>(0.0);
    for (int i = 0; i < lightSampleCount; ++i) {
        vec3 toLight = lightSamples[i] - P;
        float d = length(toLight);
        vec3 wi = normalize(toLight);
        float cosLight = max(dot(lightNormal, -wi), 0.0);
        float cosSurface = max(dot(n, wi), 0.0);
        float invD2 = float<solid_angle / (area * proj)>(1.0 / (d * d));
        float pdfW = (1.0 / lightArea) / (cosLight * invD2);
        sum += bsdf * Le * cosSurface / pdfW;
    }
    spectrum<radiance> L = sum;
    fragColor = vec4(L, 1.0);
}
