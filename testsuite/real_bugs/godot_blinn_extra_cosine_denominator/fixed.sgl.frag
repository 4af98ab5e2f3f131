#version 330 core
#include <safegi/prelude.sgl>
// An engine's normalised Blinn specular: (n + 8) / (8 pi) cos^n(theta_h) times
// N.L for one light. A leftover division by 4 N.V N.L (the Cook-Torrance
// denominator) does not belong to this lobe.
space world;

uniform point<world> light_position;
uniform spectrum<intensity> light_color;
uniform point<world> eye_position;
uniform spectrum<1> specular_color;
uniform float<1> shininess;

in point<world, shaded> vertex;
in normal<world> normal_interp;
out vec4 frag_color;

const float<brdf> INV_PI = float<brdf>(0.3183098861837907);

void main() {
    vec3 N = normalize(normal_interp);
    vec3 V = normalize(eye_position - vertex);
    vec3 light_rel = light_position - vertex;
    float dist = length(light_rel);
    vec3 L = normalize(light_rel);
    vec3 H = normalize(V + L);
    float cNdotL = max(dot(N, L), 0.0);
    float cNdotV = max(dot(N, V), 0.0);
    float cNdotH = max(dot(N, H), 0.0);
    float blinn = pow(cNdotH, shininess) * cNdotL;
    blinn *= (shininess + 8.0) / 8.0 * INV_PI;
    float specular_brdf_NL = blinn;
    float attenuation = float<solid_angle / (area * proj)>(1.0 / (dist * dist));
    spectrum<radiance> specular_light = light_color * specular_color * specular_brdf_NL * attenuation;
    frag_color = vec4(specular_light, 1.0);
}
