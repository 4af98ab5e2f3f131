#version 300 es
#include <safegi/prelude.sgl>
// A small WebGL engine's perspective camera keeps its field of view in
// degrees; the projection uses the cotangent of half of it, which wants
// radians. Written out here as the projection a vertex shader applies.
precision highp float;
space view;

uniform float<angle in degree> fov;          // vertical, as the camera stores it
uniform float aspect;
uniform float<length> near;
uniform float<length> far;

in point<view> position;

void main() {
    float fovy = fov * (3.141592653589793 / 180.0);
    float f = 1.0 / tan(fovy * 0.5);
    float z = (far + near) / (near - far) * position.z + 2.0 * far * near / (near - far);
    gl_Position = vec4(position.x * f / aspect, position.y * f, z, -position.z);
}
