#version 330 core
#include <safegi/prelude.sgl>
// A web engine's normal-map shader (Blinn-Phong in camera space): the
// perturbed normal, the light direction and the vector to the eye must all be
// in camera space for the highlight to stay put when the camera turns.
space world;
space view;

uniform direction<view> directionalLightDirection;    // toward the light
uniform spectrum<1> directionalLightColor;
uniform spectrum<1> diffuse;
uniform spectrum<1> specular;
uniform float<1> shininess;

in normal<view> vNormal;                              // after the normal map
in vector<view, away> vViewPosition;                  // from the vertex to the camera
out vec4 fragColor;

void main() {
    vec3 normal = normalize(vNormal);
    vec3 viewPosition = normalize(vViewPosition);
    vec3 dirHalfVector = normalize(directionalLightDirection + viewPosition);
    float dirDotNormalHalf = max(dot(normal, dirHalfVector), 0.0);
    float dirDiffuseWeight = max(dot(normal, directionalLightDirection), 0.0);
    float dirSpecularWeight = pow(dirDotNormalHalf, shininess);
    vec3 totalDiffuse = vec3(0.0);
    vec3 totalSpecular = vec3(0.0);
    totalDiffuse += directionalLightColor * diffuse * dirDiffuseWeight;
    totalSpecular += directionalLightColor * specular * dirSpecularWeight;
    fragColor = vec4(totalDiffuse + totalSpecular, 1.0);
}
