#version 450
#include <safegi/prelude.sgl>
// A tangent frame built around a normal by Gram-Schmidt: the bitangent is the
// cross product of two directions, whose length the checker does not know (it
// is 1 only when they are perpendicular), so the frame is linear, not rigid.
space tangent_s;
space view;

uniform normal<view> n;
uniform direction<view> around;

out vec4 color;

void main() {
    vec3 tangent = normalize(around - n * dot(around, n));
    vec3 bitangent = cross(n, tangent);
    mat3<tangent_s, view, rigid> tbn = mat3(tangent, bitangent, n);
    mat3<tangent_s, view, rigid> unit = mat3(tangent, normalize(cross(n, tangent)), n);
    mat3<tangent_s, view> linear = mat3(tangent, bitangent, n);
    color = vec4(tbn[0] + unit[1] + linear[2], 1.0);
}
