#version 450
#include <safegi/prelude.sgl>
// Tangent frames built around a normal. The cross product of two unit vectors
// has unit length exactly when they are perpendicular: Gram-Schmidt's
// x - n * dot(x, n) and cross(a, n) are perpendicular to n by construction, so
// cross(n, t) of such a t is a direction and mat3(t, b, n) a rigid frame. The
// cross product of two directions the checker does not know to be
// perpendicular is a vector of unknown length, and the frame it builds is
// linear; stored as rigid, the hint names that column.
space tangent_s;
space view;

uniform normal<view> n;
uniform direction<view> around;
uniform direction<view> up;

out vec4 color;

void main() {
    vec3 tangent = normalize(around - n * dot(around, n));
    vec3 bitangent = cross(n, tangent);
    mat3<tangent_s, view, rigid> gramSchmidt = mat3(tangent, bitangent, n);

    vec3 side = normalize(cross(up, n));
    mat3<tangent_s, view, rigid> fromUp = mat3(side, cross(n, side), n);

    vec3 skew = cross(n, around);
    mat3<tangent_s, view, rigid> notUnit = mat3(tangent, skew, n);
    mat3<tangent_s, view> linear = mat3(tangent, skew, n);
    color = vec4(gramSchmidt[0] + fromUp[1] + notUnit[2] + linear[2], 1.0);
}
