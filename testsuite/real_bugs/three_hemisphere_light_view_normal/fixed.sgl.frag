#version 330 core
#include <safegi/prelude.sgl>
// A web engine's hemisphere light: sky and ground colours blended by how far
// the world-space normal leans toward the light's world-space up direction.
space world;
space view;

uniform direction<world> hemiLightDirection;          // "up" of the hemisphere light
uniform spectrum<radiance> skyColor;
uniform spectrum<radiance> groundColor;
uniform spectrum<1> diffuseColor;

in normal<world> vNormalWorld;
in normal<view> vNormalView;
out vec4 fragColor;

void main() {
    float dotNL = dot(normalize(vNormalWorld), hemiLightDirection);
    float hemiDiffuseWeight = 0.5 * dotNL + 0.5;
    spectrum<radiance> irradianceLike = mix(groundColor, skyColor, hemiDiffuseWeight);
    fragColor = vec4(diffuseColor * irradianceLike, 1.0);
}
