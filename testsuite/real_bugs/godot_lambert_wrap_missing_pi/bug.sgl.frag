#version 330 core
#include <safegi/prelude.sgl>
// An engine's "Lambert wrap" diffuse mode (energy-conserving wrapped
// diffuse): the wrapped cosine (N.L + w) / (1 + w)^2 replaces N.L, and like
// plain Lambert it still needs the BRDF's 1 / pi.
space world;

uniform point<world> light_position;
uniform spectrum<intensity> light_color;
uniform spectrum<1> diffuse_color;
uniform float<1> roughness;

in point<world, shaded> vertex;
in normal<world> normal_interp;
out vec4 frag_color;

const float<brdf> INV_PI = float<brdf>(0.3183098861837907);

void main() {
    vec3 N = normalize(normal_interp);
    vec3 light_rel = light_position - vertex;
    float light_length = length(light_rel);
    vec3 L = normalize(light_rel);
    float NdotL = dot(N, L);
    float attenuation = float<solid_angle / (area * proj)>(1.0 / (light_length * light_length));
    float diffuse_brdf_NL = max(0.0, (NdotL + roughness) / ((1.0 + roughness) * (1.0 + roughness)));
    spectrum<radiance> diffuse_light = light_color * diffuse_color * diffuse_brdf_NL * attenuation;
    frag_color = vec4(diffuse_light, 1.0);
}
