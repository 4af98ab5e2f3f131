#version 330 core
#include <safegi/prelude.sgl>
// A creative-coding toolkit's built-in Phong shader, in eye coordinates (the
// camera at the origin): Blinn's half vector between the unit vectors to the
// light and to the eye.
space view : eye;                      // eye space: the camera at the origin

uniform point<view> lightPosition;
uniform spectrum<1> lightDiffuse;
uniform spectrum<1> lightSpecular;
uniform float<1> shininess;

in point<view, shaded> v_eyePosition;
in normal<view> v_transformedNormal;
out vec4 fragColor;

void pointLight(normal<view> normal, vector<view, away> eye, point<view, shaded> ecPosition3,
                inout vec3 diffuse, inout vec3 specular) {
    vec3 VP = lightPosition - ecPosition3;
    vec3 dirVP = normalize(VP);
    vec3 halfVector = normalize(dirVP + eye);
    float nDotVP = max(0.0, dot(normal, dirVP));
    float nDotHV = max(0.0, dot(normal, halfVector));
    float pf = nDotVP == 0.0 ? 0.0 : pow(nDotHV, shininess);
    diffuse += lightDiffuse * nDotVP;
    specular += lightSpecular * pf;
}

void main() {
    vec3 transformedNormal = normalize(v_transformedNormal);
    vector<view, away> eye = -v_eyePosition;
    vec3 diffuse = vec3(0.0);
    vec3 specular = vec3(0.0);
    pointLight(transformedNormal, eye, v_eyePosition, diffuse, specular);
    fragColor = vec4(diffuse + specular, 1.0);
}
