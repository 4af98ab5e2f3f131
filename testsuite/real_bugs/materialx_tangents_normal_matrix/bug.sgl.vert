#version 400
#include <safegi/prelude.sgl>
// A material viewer's mesh transform: positions and tangents are carried to
// world space by the world matrix, normals by its inverse transpose, so the
// tangent stays in the surface and perpendicular to the normal when the mesh
// is scaled non-uniformly.
space object;
space world;
space clip;

uniform map<object, world> u_worldMatrix;
uniform mat3<object, world, normal> u_worldInverseTransposeMatrix;
uniform projmap<world, clip> u_viewProjectionMatrix;

in point<object> i_position;
in normal<object> i_normal;
in direction<object> i_tangent;
out point<world> positionWorld;
out normal<world> normalWorld;
out direction<world> tangentWorld;

void main() {
    vec4 hPositionWorld = u_worldMatrix * vec4(i_position, 1.0);
    gl_Position = u_viewProjectionMatrix * hPositionWorld;
    positionWorld = hPositionWorld.xyz;
    normalWorld = normalize(u_worldInverseTransposeMatrix * i_normal);
    tangentWorld = normalize(u_worldInverseTransposeMatrix * i_tangent);
}
