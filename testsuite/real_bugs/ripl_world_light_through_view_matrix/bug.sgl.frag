#version 300 es
precision highp float;
#include <safegi/prelude.sgl>
// A charting library's 3D faces: each face is shaded by the Lambert term of
// its world-space normal with the light. A light in 'world' mode is given in
// world space and used as it is; a light in 'camera' mode is given in view
// space and carried back to world space by the inverse of the camera's view
// rotation, so that it follows the camera.
space world;
space view;

uniform rigidmap<world, view> viewMatrix;
uniform rigidmap<view, world> inverseViewMatrix;
uniform direction<world, away> worldLight;      // toward the light
uniform direction<view, away> cameraLight;      // toward the light
uniform bool cameraMode;
uniform vec3 baseColor;
uniform float<1> ambient;

in normal<world> worldNormal;
out vec4 fragColor;

void main() {
    vec3 n = normalize(worldNormal);
    vec3 l = cameraMode ? cameraLight : (viewMatrix * vec4(worldLight, 0.0)).xyz;
    float brightness = ambient + (1.0 - ambient) * max(dot(n, l), 0.0);
    fragColor = vec4(baseColor * brightness, 1.0);
}
