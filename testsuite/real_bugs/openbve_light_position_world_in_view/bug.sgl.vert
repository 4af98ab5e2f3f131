#version 150
#include <safegi/prelude.sgl>
// A train simulator's GL 3 lighting shader lights in view space: the
// world's single directional light (given as a direction toward the sun, as
// fixed-function GL took it) is carried by the current view matrix before the
// Lambert cosine with the view-space normal.
space world;
space view;
space clip;

uniform map<world, view> uCurrentModelViewMatrix;
uniform rigidmap<world, view> uCurrentViewMatrix;
uniform projmap<view, clip> uCurrentProjectionMatrix;
uniform direction<world> uLightPosition;     // toward the light, w = 0
uniform vec3 uLightDiffuse;
uniform vec3 uLightAmbient;

in point<world> iPosition;
in normal<world> iNormal;
out vec3 oColor;

void main() {
    vec3 eyeNormal = normalize((vec4(iNormal, 0.0) * inverse(uCurrentModelViewMatrix)).xyz);
    vec3 lightDir = uLightPosition;
    float nDotL = max(dot(eyeNormal, lightDir), 0.0);
    oColor = uLightAmbient + uLightDiffuse * nDotL;
    gl_Position = uCurrentProjectionMatrix * uCurrentModelViewMatrix * vec4(iPosition, 1.0);
}
