#version 330 core
#include <safegi/prelude.sgl>
// A clustered forward renderer's point light, shaded in view space: the
// light's world position is carried into view space as a point (w = 1) and
// only its xyz enter the light vector and the distance falloff.
space world;
space view;

uniform map<world, view> viewMatrix;
uniform point<world> lightWorldPosition;
uniform spectrum<intensity> lightColor;
uniform float<length> cutoffDistance;
uniform spectrum<brdf> diffuseColor;

in point<view, shaded> vViewPosition;
in normal<view> vNormal;
out vec4 fragColor;

void main() {
    vec4 lightViewPosition = viewMatrix * vec4(lightWorldPosition, 1.0);
    vec4 lVector = lightViewPosition - vec4(vViewPosition, 0.0);
    float lightDistance = length(lVector);
    direction<view, away> lightDir = normalize(lVector.xyz);
    float range = pow(clamp(1.0 - pow(lightDistance / cutoffDistance, 4), 0.0, 1.0), 2.0);
    float falloff = float<solid_angle / (area * proj)>(range / (lightDistance * lightDistance));
    float dotNL = max(dot(normalize(vNormal), lightDir), 0.0);
    spectrum<radiance> outgoing = diffuseColor * lightColor * falloff * dotNL;
    fragColor = vec4(outgoing, 1.0);
}
