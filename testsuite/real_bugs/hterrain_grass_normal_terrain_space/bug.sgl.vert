#version 330 core
#include <safegi/prelude.sgl>
// A terrain plugin's grass (detail layer) vertex shader: each grass instance
// is snapped to the heightmap under it and shaded with the terrain's normal
// there, read from the terrain's normal map. That normal is in the terrain's
// own space, which the terrain node may scale; the host uploads the normal
// matrix (the inverse transpose of the terrain's basis) to carry it to world.
space object;
space terrain;
space world;
space clip;

uniform map<world, terrain> u_terrain_inverse_transform;
uniform mat3<terrain, world, normal> u_terrain_normal_basis;
uniform map<object, world> WORLD_MATRIX;
uniform projmap<world, clip> VIEW_PROJECTION;
uniform sampler2D u_terrain_heightmap;
uniform sampler2D u_terrain_normalmap;

in point<object> VERTEX;
out normal<world> v_normal;
out vec2 v_map_uv;

vec3 unpack_normal(vec4 rgba) {
    return rgba.xzy * 2.0 - vec3(1.0);
}

void main() {
    vec4 obj_pos = WORLD_MATRIX * vec4(0.0, 1.0, 0.0, 1.0);
    vec3 cell_coords = (u_terrain_inverse_transform * obj_pos).xyz;
    vec2 map_uv = cell_coords.xz / vec2(textureSize(u_terrain_heightmap, 0));
    v_map_uv = map_uv;

    vec3 p = VERTEX;
    p.y += texture(u_terrain_heightmap, map_uv).r / cell_coords.y;
    gl_Position = VIEW_PROJECTION * WORLD_MATRIX * vec4(p, 1.0);

    normal<terrain> n = normal<terrain>(unpack_normal(texture(u_terrain_normalmap, map_uv)) * vec3(1.0, 1.0, -1.0));
    v_normal = n;
}
