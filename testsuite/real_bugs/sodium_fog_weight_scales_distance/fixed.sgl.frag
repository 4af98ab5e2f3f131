#version 330 core
#include <safegi/prelude.sgl>
// A block-game renderer's linear fog: the blend factor rises from 0 at the fog
// start distance to 1 at its end; the fog color's alpha is the fog's weight,
// which scales the blend factor, not the distance.
uniform vec4 u_FogColor;                  // alpha: fog weight
uniform float<length> u_FogStart;
uniform float<length> u_FogEnd;

in float<length> v_FragDistance;
in vec4 v_Color;
out vec4 fragColor;

vec4 _linearFog(vec4 fragColor, float<length> fragDistance, vec4 fogColor, float<length> fogStart, float<length> fogEnd) {
    if (fragDistance <= fogStart) {
        return fragColor;
    }
    float factor = fragDistance < fogEnd ? smoothstep(fogStart, fogEnd, fragDistance) : 1.0;
    vec3 blended = mix(fragColor.rgb, fogColor.rgb, factor * fogColor.a);
    return vec4(blended, fragColor.a);
}

void main() {
    fragColor = _linearFog(v_Color, v_FragDistance, u_FogColor, u_FogStart, u_FogEnd);
}
