#version 450
#include <safegi/prelude.sgl>
// An engine's screen-space reflections with an orthographic camera: every
// view ray is parallel to the camera's -z axis, so the direction from the eye
// to a pixel is the constant (0, 0, -1); normalizing the view-space position
// gives the perspective camera's rays and bends the reflections.
space view : eye;

uniform sampler2D<normal<view>> normalRoughness;
uniform sampler2D<point<view>> viewPositions;

in vec2 uv;
out vec4 reflectedRay;

void main() {
    point<view, shaded> P = texture(viewPositions, uv).xyz;
    normal<view> N = normalize(texture(normalRoughness, uv).xyz);
    direction<view, toward> viewDir = direction<view, toward>(vec3(0.0, 0.0, -1.0));
    direction<view> rayDir = reflect(viewDir, N);
    reflectedRay = vec4(rayDir, 1.0);
}
