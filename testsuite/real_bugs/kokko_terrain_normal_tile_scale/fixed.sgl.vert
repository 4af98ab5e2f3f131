#version 450
#include <safegi/prelude.sgl>
// A C++ engine's terrain vertex shader: a tile's grid position (in [0, 1])
// is placed in the world by the terrain size and the tile's scale, its height
// read from a heightmap. The normal comes from central differences of the
// height: the slope angle over the horizontal distance between the two
// samples, which must include the tile scale like the positions do.
space world;
space view;
space clip;

layout(std140, binding = 1) uniform TerrainBlock {
    projmap<world, clip> MVP;
    rigidmap<world, view> MV;
    vec2 tile_offset;
    float tile_scale;
    float<length> terrain_size;
    float terrain_resolution;
    float<length> height_origin;
    float<length> height_range;
} uniforms;

layout(location = 0) in vec2 position;
out normal<view> vs_normal;
uniform sampler2D height_map;

float sample_height(vec2 offset) {
    return texture(height_map, position + offset).r;
}

void main() {
    float offset_amount = 1.0 / uniforms.terrain_resolution;
    float<length> y_extent = uniforms.height_range;
    float<length> w_offset = uniforms.terrain_size * uniforms.tile_scale / uniforms.terrain_resolution * 2.0;

    float h0 = sample_height(vec2(0.0, 0.0));
    float h1 = sample_height(vec2(offset_amount, 0.0));
    float h2 = sample_height(vec2(-offset_amount, 0.0));
    float h3 = sample_height(vec2(0.0, offset_amount));
    float h4 = sample_height(vec2(0.0, -offset_amount));

    float<length> x_diff = (h2 - h1) * y_extent;
    float<length> z_diff = (h4 - h3) * y_extent;
    float<angle> x_angle = atan(x_diff, w_offset);
    float<angle> z_angle = atan(z_diff, w_offset);
    vec3 x_tan = vec3(cos(x_angle), -sin(x_angle), 0.0);
    vec3 z_tan = vec3(0.0, -sin(z_angle), cos(z_angle));
    normal<world> w_normal = normal<world>(cross(normalize(z_tan), normalize(x_tan)));

    vec2 w_pos = (position + uniforms.tile_offset) * uniforms.terrain_size * uniforms.tile_scale;
    point<world> p = point<world>(vec3(w_pos.x, uniforms.height_origin + h0 * y_extent, w_pos.y));
    gl_Position = uniforms.MVP * vec4(p, 1.0);
    vs_normal = normalize(vec3(uniforms.MV * vec4(w_normal, 0.0)));
}
