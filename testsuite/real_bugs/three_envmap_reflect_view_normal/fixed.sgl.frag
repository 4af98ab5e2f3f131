#version 330 core
#include <safegi/prelude.sgl>
// A web engine's environment map with a normal map: the perturbed normal is
// in camera space, the cube map in world space, so the normal is carried back
// to world space (the view matrix is a rotation plus a translation) before the
// world-space view vector is reflected about it.
space world;
space view;

uniform rigidmap<view, world> inverseViewRotation;    // transpose of the view matrix's rotation
uniform point<world> cameraPosition;
uniform samplerCube<spectrum<radiance>> envMap;
uniform float<1> reflectivity;
uniform spectrum<radiance> litColor;

in point<world, shaded> vWorldPosition;
in normal<view> vNormal;                              // camera space, after the normal map
out vec4 fragColor;

void main() {
    vec3 cameraToVertex = normalize(vWorldPosition - cameraPosition);
    vec3 worldNormal = normalize(inverseViewRotation * normalize(vNormal));
    vec3 reflectVec = reflect(cameraToVertex, worldNormal);
    spectrum<radiance> envColor = texture(envMap, reflectVec).rgb;
    fragColor = vec4(mix(litColor, envColor, reflectivity), 1.0);
}
