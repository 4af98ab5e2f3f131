#version 330 core
#include <safegi/prelude.sgl>
// A visual-programming DX11 pack's spot light buffer, with a view transform
// given: the light's position is carried to view space as a point and its
// direction as a direction (w = 0), each from its own input.
space world;
space view;

uniform rigidmap<world, view> tV;
uniform point<world> spotPosition;
uniform direction<world> spotDirection;

out point<view> lightPosV;
out direction<view> lightDirV;

void main() {
    lightPosV = (tV * vec4(spotPosition, 1.0)).xyz;
    lightDirV = (tV * vec4(spotDirection, 0.0)).xyz;
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
