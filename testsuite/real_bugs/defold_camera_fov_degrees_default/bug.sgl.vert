#version 330 core
#include <safegi/prelude.sgl>
// A 2D/3D game engine's camera template: the camera component's field of
// view is in radians (the engine passes it to its perspective matrix as is),
// so the template's default of 45 degrees is written as 0.785 radians. The
// vertex stage builds the perspective projection from it.
space view;
space clip;

const float<angle> cameraFov = 45.0;           // the template's default
uniform float<1> aspectRatio;
uniform float<length> nearZ;
uniform float<length> farZ;

in point<view> position;

void main() {
    float f = 1.0 / tan(cameraFov * 0.5);
    float a = (farZ + nearZ) / (nearZ - farZ);
    float b = 2.0 * farZ * nearZ / (nearZ - farZ);
    gl_Position = vec4(f / aspectRatio * position.x, f * position.y, a * position.z + b, -position.z);
}
