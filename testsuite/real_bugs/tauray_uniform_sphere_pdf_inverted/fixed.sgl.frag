#version 460
#include <safegi/prelude.sgl>
// A Vulkan path tracer's next-event estimation toward the environment: with
// an environment map the direction is drawn from an alias table (its pdf per
// solid angle stored with each entry); with a constant environment it is
// drawn uniformly over the sphere, whose pdf is 1 / (4 pi) per steradian.
// The estimate divides radiance times BRDF times cosine by that pdf.
#define M_PI 3.14159265359
space world;

struct alias_table_entry {
    uint alias_id;
    float probability;
    float<pdf_solid_angle> pdf;
    float<pdf_solid_angle> alias_pdf;
};
layout(binding = 0) readonly buffer alias_table_buffer { alias_table_entry entries[]; } environment_map_alias_table;
uniform sampler2D environment_map_tex;            // texels scale the factor
uniform int environment_proj;
uniform spectrum<radiance> environment_factor;
uniform spectrum<brdf> albedo_over_pi;

flat in normal<world> hitNormal;
flat in uvec2 rand;
out vec4 outColor;

direction<world> sample_sphere(vec2 u) {
    float cos_theta = 2.0 * u.x - 1.0;
    float sin_theta = sqrt(max(0.0, 1.0 - cos_theta * cos_theta));
    float phi = 2.0 * M_PI * u.y;
    return direction<world>(vec3(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta));
}

direction<world> uv_to_latlong_direction(vec2 uv) {
    float theta = uv.y * M_PI;
    float phi = uv.x * 2.0 * M_PI;
    return direction<world>(vec3(sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi)));
}

spectrum<radiance> sample_environment_map(uvec2 r, out direction<world> dir, out float<pdf_solid_angle> pdf) {
    spectrum<radiance> color = environment_factor;
    if (environment_proj >= 0) {
        uvec2 size = uvec2(textureSize(environment_map_tex, 0));
        uint pixel_count = size.x * size.y;
        int i = int(r.x % pixel_count);
        alias_table_entry at = environment_map_alias_table.entries[i];
        pdf = at.pdf;
        if (float(r.y) / 4294967296.0 > at.probability) {
            i = int(at.alias_id);
            pdf = at.alias_pdf;
        }
        vec2 uv = (vec2(i % int(size.x), i / int(size.x)) + 0.5) / vec2(size);
        dir = uv_to_latlong_direction(uv);
        color *= texture(environment_map_tex, uv).rgb;
    } else {
        pdf = 1.0 / (4.0 * M_PI);
        dir = sample_sphere(ldexp(vec2(r), ivec2(-32)));
    }
    return color;
}

void main() {
    direction<world> dir;
    float<pdf_solid_angle> pdf;
    spectrum<radiance> Le = sample_environment_map(rand, dir, pdf);
    float cosI = max(dot(hitNormal, dir), 0.0);
    spectrum<radiance> contrib = albedo_over_pi * Le * cosI / pdf;
    outColor = vec4(contrib, 1.0);
}
