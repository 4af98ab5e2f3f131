#version 300 es
#include <safegi/prelude.sgl>
// A creative-coding library's per-vertex point lights: the normal, carried to
// view space by the normal matrix (which scales when the model is scaled), is
// normalized before it takes part in the Lambert cosine.
precision highp float;
space object;
space view;
space clip;

uniform map<object, view> uModelViewMatrix;
uniform projmap<view, clip> uProjectionMatrix;
uniform mat3<object, view, normal> uNormalMatrix;
uniform int uPointLightCount;
uniform point<view> uPointLightLocation[5];
uniform spectrum<irradiance / proj> uPointLightColor[5];   // on a surface facing the light

in point<object, shaded> aPosition;
in normal<object> aNormal;
out spectrum<irradiance> vDiffuseColor;

void main() {
    vec4 mvPosition = uModelViewMatrix * vec4(aPosition, 1.0);
    vec3 vertexNormal = uNormalMatrix * aNormal;
    vec3 diffuse = vec3(0.0);
    for (int j = 0; j < 5; j++) {
        if (j >= uPointLightCount) break;
        vec3 lightDir = normalize(uPointLightLocation[j] - mvPosition.xyz);
        float pointLightWeighting = max(dot(lightDir, vertexNormal), 0.0);
        diffuse += uPointLightColor[j] * pointLightWeighting;
    }
    vDiffuseColor = diffuse;
    gl_Position = uProjectionMatrix * mvPosition;
}
