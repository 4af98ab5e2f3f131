#version 330 core
#include <safegi/prelude.sgl>
// 3×3 maps compose: two rotations give a rotation; a normal matrix and a rotation
// (its own normal matrix) give a normal matrix, N(R M) = R N(M); a normal matrix
// with a linear map that may scale does not, nor do maps whose spaces do not meet.
space object;
space view;
space world;
uniform mat3<view, world, rigid> viewToWorld;
uniform mat3<object, view, normal> normalMatrix;
uniform mat3<view, world> stretch;
uniform mat3<world, view, rigid> worldToView;
in normal<object> n;
out normal<world> worldNormal;
void main() {
    worldNormal = normalize(viewToWorld * normalMatrix * n);
    mat3<view, view, rigid> identity = worldToView * viewToWorld;
    vec3 scaled = stretch * normalMatrix * n;
    vec3 crossed = normalMatrix * viewToWorld * n;
    gl_Position = vec4(identity * vec3(0.0), 1.0);
}
