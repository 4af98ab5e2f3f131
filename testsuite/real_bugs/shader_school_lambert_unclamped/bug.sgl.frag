#version 300 es
#include <safegi/prelude.sgl>
// A shader tutorial's Lambert exercise: the diffuse weight is the cosine to
// the light, clamped at zero so that faces turned away from the light get
// only the ambient term instead of a negative contribution.
precision highp float;
space view;

uniform direction<view> lightDirection;     // toward the light
uniform vec3 ambient;
uniform vec3 diffuse;

in normal<view> fragNormal;
out vec4 fragColor;

void main() {
    vec3 N = normalize(fragNormal);
    float lambert = dot(N, lightDirection);
    fragColor = vec4(ambient + diffuse * lambert, 1.0);
}
