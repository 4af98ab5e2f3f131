#version 450
#include <safegi/prelude.sgl>
// A render pipeline's percentage-closer soft shadows read a light's shadow
// map out of a shared atlas: the blocker search and the filter offsets are
// given in the shadow map's own texture coordinates, so in atlas coordinates
// they are scaled by the map's share of the atlas (map size / atlas size);
// unscaled, doubling the atlas resolution doubles the penumbra.
uniform sampler2D shadowAtlas;
uniform vec2 shadowMapSizeInAtlas;           // the map's size as a fraction of the atlas
uniform vec2 shadowMapOffsetInAtlas;
uniform float filterRadius;                  // in the shadow map's texture coordinates
uniform vec2 poisson[16];

in vec3 shadowCoord;                         // the map's texture coordinates and depth
out vec4 fragColor;

void main() {
    vec2 atlasUv = shadowMapOffsetInAtlas + shadowCoord.xy * shadowMapSizeInAtlas;
    vec2 radiusAtlas = filterRadius * shadowMapSizeInAtlas;
    float lit = 0.0;
    for (int i = 0; i < 16; i++) {
        float blocker = texture(shadowAtlas, atlasUv + poisson[i] * radiusAtlas).r;
        lit += shadowCoord.z <= blocker ? 1.0 : 0.0;
    }
    fragColor = vec4(vec3(lit / 16.0), 1.0);
}
