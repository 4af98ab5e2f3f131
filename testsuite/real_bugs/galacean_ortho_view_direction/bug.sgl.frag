#version 300 es
#include <safegi/prelude.sgl>
// Web engine's Blinn-Phong highlight, view direction. With a perspective camera
// V points from the fragment to the camera; with an orthographic camera every
// view ray is parallel to the camera's forward axis, so V is that axis
// reversed wherever the fragment is. This is the orthographic variant the fix
// added (CAMERA_ORTHOGRAPHIC).
precision highp float;
space world;

uniform point<world> camera_Position;
uniform direction<world> camera_Forward;
uniform direction<world> lightDirection;     // the direction the light travels
uniform vec3 lightColor;
uniform vec3 specularColor;
uniform float shininess;

in point<world, shaded> v_pos;
in normal<world> v_normal;
out vec4 fragColor;

void main() {
    vec3 N = normalize(v_normal);
    vec3 V = normalize(camera_Position - v_pos);
    vec3 L = -lightDirection;
    vec3 H = normalize(L + V);
    float s = pow(clamp(dot(N, H), 0.0, 1.0), shininess);
    fragColor = vec4(lightColor * specularColor * s, 1.0);
}
