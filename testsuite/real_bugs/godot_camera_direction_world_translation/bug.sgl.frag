#version 450
#include <safegi/prelude.sgl>
// A game engine's built-in CAMERA_DIRECTION_WORLD, here feeding a rim term:
// the camera's view axis in world space is the z column of the inverse view
// matrix (camera to world), not a column of the view matrix.
space world;
space view;

layout(set = 0, binding = 0) uniform SceneData {
    map<world, view> view_matrix;
    map<view, world> inv_view_matrix;
} scene_data;

layout(location = 0) in normal<world> normal_world;
layout(location = 0) out vec4 frag_color;

void main() {
    vec3 camera_direction_world = scene_data.view_matrix[3].xyz;
    vec3 N = normalize(normal_world);
    float rim = 1.0 - abs(dot(N, normalize(camera_direction_world)));
    frag_color = vec4(vec3(rim), 1.0);
}
