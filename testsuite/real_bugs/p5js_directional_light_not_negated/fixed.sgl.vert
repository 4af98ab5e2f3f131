#version 300 es
#include <safegi/prelude.sgl>
// A creative-coding library's per-vertex lighting: a directional light is
// given by the direction its light travels (as Processing defines it), so the
// Lambert cosine is taken with the opposite direction, toward the light.
precision highp float;
space object;
space view;
space clip;

uniform map<object, view> uModelViewMatrix;
uniform projmap<view, clip> uProjectionMatrix;
uniform mat3<object, view, normal> uNormalMatrix;
uniform int uDirectionalLightCount;
uniform direction<view, toward> uLightingDirection[5];   // the light's travel direction
uniform spectrum<irradiance / proj> uDirectionalDiffuseColors[5];   // on a surface facing the light

in point<object> aPosition;
in normal<object> aNormal;
out spectrum<irradiance> vDiffuseColor;

void main() {
    vec3 vertexNormal = normalize(uNormalMatrix * aNormal);
    vec3 diffuse = vec3(0.0);
    for (int j = 0; j < 5; j++) {
        if (j >= uDirectionalLightCount) break;
        vec3 dir = uLightingDirection[j];
        float directionalLightWeighting = max(dot(vertexNormal, -dir), 0.0);
        diffuse += uDirectionalDiffuseColors[j] * directionalLightWeighting;
    }
    vDiffuseColor = diffuse;
    gl_Position = uProjectionMatrix * uModelViewMatrix * vec4(aPosition, 1.0);
}
