#version 330 core
#include <safegi/prelude.sgl>
// A face-mask plugin's Phong shader, point and spot lights: the distance
// attenuation 1 / (c + l d + q d^2) uses the distance d from the light's
// position to the shaded point, and is saturated so a light never exceeds
// its full intensity.
space view;

uniform point<view> lightPosition;
uniform direction<view> lightDirection;     // spot axis, from the light
uniform vec3 lightColor;
uniform float<1> attConstant;
uniform float<inv_length> attLinear;
uniform float<inv_area> attQuadratic;
uniform vec3 diffuseColor;

in point<view, shaded> vPosition;
in normal<view> vNormal;
out vec4 fragColor;

void main() {
    normal<view> n = normalize(vNormal);
    vector<view, away> toLight = lightPosition - vPosition;
    float<length> d = length(lightDirection);
    direction<view, away> l = normalize(toLight);
    float att = 1.0 / (attConstant + attLinear * d + attQuadratic * d * d);
    float<proj> cosL = max(dot(n, l), 0.0);
    fragColor = vec4(diffuseColor * lightColor * cosL * att, 1.0);
}
