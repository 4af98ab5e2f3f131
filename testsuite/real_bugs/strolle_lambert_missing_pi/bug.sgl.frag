#version 330 core
#include <safegi/prelude.sgl>
// A real-time path tracer's frame composition: the resolved direct diffuse
// lighting is the irradiance sum of the light samples (Li cos / pdf); the
// Lambertian BRDF that turns it into outgoing radiance is albedo / pi.
space world;

uniform sampler2D<spectrum<1>> albedoTexture;
uniform sampler2D<spectrum<radiance>> lightSampleRadiance;   // Li of the chosen light sample
uniform sampler2D<direction<world>> lightSampleDirection;
uniform sampler2D<normal<world>> gbufferNormal;
uniform sampler2D<float<pdf_solid_angle>> lightSamplePdf;

in vec2 uv;
out vec4 color;

const float<brdf> INV_PI = float<brdf>(0.3183098861837907);

void main() {
    spectrum<1> albedo = texture(albedoTexture, uv).rgb;
    spectrum<radiance> Li = texture(lightSampleRadiance, uv).rgb;
    vec3 N = texture(gbufferNormal, uv).xyz;
    vec3 L = texture(lightSampleDirection, uv).xyz;
    float pdf = texture(lightSamplePdf, uv).r;
    spectrum<irradiance> diDiffuse = Li * max(dot(N, L), 0.0) / pdf;
    spectrum<radiance> diffuse = albedo * diDiffuse;
    color = vec4(diffuse, 1.0);
}
