#version 330 core
#include <safegi/prelude.sgl>
// Orthographic view that matches a perspective camera at a focus distance:
// the frustum's half height there is tan(fov / 2) times the distance; the
// camera's field of view is kept in degrees.
space view;

uniform float<angle in degree> fov;
uniform float<length> hyperfocus;
uniform float<1> aspect;
uniform float<length> near;
uniform float<length> far;

in point<view> position;

void main() {
    float halfHeight = tan(radians(fov) * 0.5) * hyperfocus;
    float halfWidth = halfHeight * aspect;
    float depth = (-position.z - near) / (far - near);
    gl_Position = vec4(position.x / halfWidth, position.y / halfHeight, depth * 2.0 - 1.0, 1.0);
}
