#version 330 core
#include <safegi/prelude.sgl>
// A scene-graph library's reflection map: the cube map is indexed in world
// space, so the eye and normal vectors (view space, where normal mapping
// perturbed the normal) are carried back to world space first.
space world;
space view;

uniform rigidmap<view, world> worldFromView;
uniform samplerCube<spectrum<radiance>> reflectionCube;
uniform float<1> reflectionIntensity;
uniform spectrum<radiance> baseColor;

in direction<view, toward> vViewEyeVec;               // from the eye toward the surface
in normal<view> vViewNormal;
out vec4 fragColor;

void main() {
    vec3 worldEyeVec = normalize(worldFromView * vViewEyeVec);
    vec3 worldNormal = normalize(worldFromView * vViewNormal);
    direction<world, away> envLookup = reflect(vViewEyeVec, normalize(vViewNormal));
    spectrum<radiance> reflectColor = texture(reflectionCube, envLookup).rgb;
    fragColor = vec4(baseColor + reflectionIntensity * reflectColor, 1.0);
}
