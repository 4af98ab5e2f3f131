#version 330 core
#include <safegi/prelude.sgl>
// A rendering library's image-based-lighting example draws the sky as a
// screen quad: each corner's view ray is built from the vertical field of
// view (tan of half of it, in radians) and the viewport's aspect ratio, and
// turned to world space by the camera's rotation.
space view;
space world;
space clip;

uniform rigidmap<view, world> u_mtx;
uniform projmap<world, clip> u_modelViewProj;
uniform vec4 u_viewRect;

in point<world> a_position;
in vec2 a_texcoord0;
out vec3 v_dir;

void main() {
    gl_Position = u_modelViewProj * vec4(a_position, 1.0);

    float fov = 45.0;
    float height = tan(fov * 0.5);
    float aspect = height * (u_viewRect.z / u_viewRect.w);
    vec2 tex = (2.0 * a_texcoord0 - 1.0) * vec2(aspect, height);

    v_dir = (u_mtx * vec4(tex, 1.0, 0.0)).xyz;
}
