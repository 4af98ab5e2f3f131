#version 300 es
#include <safegi/prelude.sgl>
// A tiny WebGL framework's lit fragment shader: the vertex shader outputs
// unit normals, but they are interpolated across the triangle, so the
// fragment normalises again before taking the cosine to the light.
precision highp float;
space world;

uniform direction<world> light;           // toward the light
uniform vec3 ambientColor;
uniform vec3 color;

in normal<world> v_normal;
out vec4 fragColor;

void main() {
    vec3 N = v_normal;
    float nDotL = max(dot(N, light), 0.0);
    fragColor = vec4(color * (ambientColor + nDotL), 1.0);
}
