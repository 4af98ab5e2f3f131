#version 330 core
#include <safegi/prelude.sgl>
// A real-time path tracer's frame composition: the resolved direct diffuse
// lighting is the irradiance sum of the light samples (Li cos / pdf); the
// Lambertian BRDF that turns it into outgoing radiance is albedo / pi. The
// pass reads its inputs texel for texel (WGSL textureLoad: texelFetch).
space world;

uniform sampler2D<spectrum<1>> albedoTexture;
uniform sampler2D<spectrum<radiance>> lightSampleRadiance;   // Li of the chosen light sample
uniform sampler2D<direction<world>> lightSampleDirection;
uniform sampler2D<normal<world>> gbufferNormal;
uniform sampler2D<float<pdf_solid_angle>> lightSamplePdf;

out vec4 color;

const float<brdf> INV_PI = float<brdf>(0.3183098861837907);

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    spectrum<1> albedo = texelFetch(albedoTexture, px, 0).rgb;
    spectrum<radiance> Li = texelFetch(lightSampleRadiance, px, 0).rgb;
    vec3 N = texelFetch(gbufferNormal, px, 0).xyz;
    vec3 L = texelFetch(lightSampleDirection, px, 0).xyz;
    float pdf = texelFetch(lightSamplePdf, px, 0).r;
    spectrum<irradiance> diDiffuse = Li * max(dot(N, L), 0.0) / pdf;
    spectrum<radiance> diffuse = albedo * INV_PI * diDiffuse;
    color = vec4(diffuse, 1.0);
}
