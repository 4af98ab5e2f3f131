#version 330 core
#include <safegi/prelude.sgl>
// An emulator CRT shader's geometry pass tilts the simulated tube: a rotation
// about x by the vertical tilt, then about y by the horizontal one. The
// local-to-global rotation is the product of the two; being a rotation, its
// transpose is its inverse, whose rows the fragment stage receives.
uniform vec2<angle> geom_tilt_angle;

in vec4 Position;
out vec3 global_to_local_row0;
out vec3 global_to_local_row1;
out vec3 global_to_local_row2;

void main() {
    vec2 sin_tilt = sin(geom_tilt_angle);
    vec2 cos_tilt = cos(geom_tilt_angle);
    // rows as written, transposed into GLSL's column-major constructor
    mat3 rot_x_matrix = transpose(mat3(
        1.0, 0.0, 0.0,
        0.0, cos_tilt.y, -sin_tilt.y,
        0.0, sin_tilt.y, cos_tilt.y));
    mat3 rot_y_matrix = transpose(mat3(
        cos_tilt.x, 0.0, sin_tilt.x,
        0.0, 1.0, 0.0,
        -sin_tilt.x, 0.0, cos_tilt.x));
    mat3 local_to_global = transpose(mat3(
        cos_tilt.x, sin_tilt.y * sin_tilt.x, cos_tilt.y * sin_tilt.x,
        0.0, cos_tilt.y, sin_tilt.y,
        sin_tilt.x, sin_tilt.y * cos_tilt.x, cos_tilt.y * cos_tilt.x));
    mat3 global_to_local = transpose(local_to_global);
    global_to_local_row0 = vec3(global_to_local[0][0], global_to_local[1][0], global_to_local[2][0]);
    global_to_local_row1 = vec3(global_to_local[0][1], global_to_local[1][1], global_to_local[2][1]);
    global_to_local_row2 = vec3(global_to_local[0][2], global_to_local[1][2], global_to_local[2][2]);
    gl_Position = Position;
}
