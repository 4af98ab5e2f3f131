#version 330 core
#include <safegi/prelude.sgl>
// A scene package's unskinned vertex shader: world-space position, normal and
// view vector for the standard material. The normal takes the inverse
// transpose of the model transform's upper 3x3.
space object;
space world;
space clip;

uniform FrameInfo {
    map<object, world> model_transform;
    projmap<world, clip> camera_transform;
    point<world> camera_position;
} frame_info;

in point<object> position;
in normal<object> normal;
out point<world> v_position;
out normal<world> v_normal;
in vec2 texture_coords;
out vector<world> v_viewvector;
out vec2 v_texture_coords;

void main() {
    vec4 model_position = frame_info.model_transform * vec4(position, 1.0);
    v_position = model_position.xyz;
    gl_Position = frame_info.camera_transform * model_position;
    v_viewvector = frame_info.camera_position - v_position;
    v_normal = transpose(inverse(mat3(frame_info.model_transform))) * normal;
    v_texture_coords = texture_coords;
}
