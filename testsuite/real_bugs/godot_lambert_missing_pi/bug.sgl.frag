#version 330 core
#include <safegi/prelude.sgl>
// An engine's per-light Lambert term: the energy-conserving BRDF is
// albedo / pi, so the factor the light colour is scaled by is N.L / pi.
space world;

uniform point<world> light_position;
uniform spectrum<intensity> light_color;
uniform spectrum<1> diffuse_color;

in point<world, shaded> vertex;
in normal<world> normal_interp;
out vec4 frag_color;

const float<brdf> INV_PI = float<brdf>(0.3183098861837907);

void main() {
    vec3 N = normalize(normal_interp);
    vec3 light_rel = light_position - vertex;
    float light_length = length(light_rel);
    vec3 L = normalize(light_rel);
    float NdotL = max(dot(N, L), 0.0);
    float attenuation = float<solid_angle / (area * proj)>(1.0 / (light_length * light_length));
    float diffuse_brdf_NL = NdotL;
    spectrum<radiance> diffuse_light = light_color * diffuse_color * diffuse_brdf_NL * attenuation;
    frag_color = vec4(diffuse_light, 1.0);
}
