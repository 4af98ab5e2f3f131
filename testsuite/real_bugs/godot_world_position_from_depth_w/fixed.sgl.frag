#version 330 core
#include <safegi/prelude.sgl>
// A visual-shader node that reconstructs the world position behind a pixel
// from the depth buffer: NDC through the inverse projection gives a
// homogeneous view-space point, divided by its w before the camera-to-world
// transform.
space clip;
space view;
space world;

uniform sampler2D<float<1>> depth_texture;           // window depth in [0, 1]
uniform projmap<clip, view> inv_projection_matrix;
uniform rigidmap<view, world> inv_view_matrix;
uniform float<length> fade_height;

in vec2 screen_uv;
out vec4 albedo;

void main() {
    float depth = texture(depth_texture, screen_uv).x;
    vec3 ndc = vec3(screen_uv * 2.0 - 1.0, depth * 2.0 - 1.0);
    vec4 depth_view = inv_projection_matrix * vec4(ndc, 1.0);
    depth_view /= depth_view.w;
    vec3 world_position = (inv_view_matrix * depth_view).xyz;
    float<length> height = world_position.y;
    albedo = vec4(vec3(clamp(height / fade_height, 0.0, 1.0)), 1.0);
}
