#version 330 core
#include <safegi/prelude.sgl>
// A direction carried by a declared normal matrix: the inverse transpose is for
// normals. When the matrix is a rotation (a camera's view), it is its own
// normal matrix, which its declaration says with `rigid`: the hint's
// declaration (viewRotation below) then carries directions and normals alike.
space world;
space eye;
uniform direction<world> lightDirection;
uniform mat3<world, eye, normal> normalMatrix;
uniform mat3<world, eye, rigid> viewRotation;
in normal<eye> n;
out vec4 fragColor;
void main() {
    vec3 wrong = normalize(normalMatrix * lightDirection);
    vec3 l = viewRotation * lightDirection;
    float<proj> c = max(dot(normalize(n), -l), 0.0);
    fragColor = vec4(c);
}
