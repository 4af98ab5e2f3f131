#version 330 core
#include <safegi/prelude.sgl>
// An engine's per-light pass with Disney (Burley) diffuse: the normalised
// BRDF times the light's irradiance, which needs the receiver's cosine N.L.
space world;

uniform point<world> light_pos;
uniform spectrum<intensity> light_color;        // omni light
uniform point<world> eye_pos;
uniform spectrum<1> albedo;
uniform float<1> roughness;

in point<world, shaded> vertex;
in normal<world> normal_interp;
out vec4 frag_color;

const float<brdf> INV_PI = float<brdf>(0.318309886);

float SchlickFresnel(float u) {
    float m = 1.0 - u;
    float m2 = m * m;
    return m2 * m2 * m;
}

void main() {
    vec3 N = normalize(normal_interp);
    vec3 V = normalize(eye_pos - vertex);
    vec3 to_light = light_pos - vertex;
    float dist = length(to_light);
    vec3 L = normalize(to_light);
    vec3 H = normalize(V + L);
    float NdotL = max(dot(N, L), 0.0);
    float NdotV = max(dot(N, V), 0.0);
    float LdotH = max(dot(L, H), 0.0);

    float FD90 = 0.5 + 2.0 * LdotH * LdotH * roughness;
    float FdV = 1.0 + (FD90 - 1.0) * SchlickFresnel(NdotV);
    float FdL = 1.0 + (FD90 - 1.0) * SchlickFresnel(NdotL);
    float<brdf> diffuse_brdf = INV_PI * FdV * FdL;
    float diffuse_brdf_NL = diffuse_brdf;

    float attenuation = float<solid_angle / (area * proj)>(1.0 / (dist * dist));
    spectrum<radiance> diffuse_light = albedo * light_color * attenuation * diffuse_brdf_NL;
    frag_color = vec4(diffuse_light, 1.0);
}
