#version 300 es
#include <safegi/prelude.sgl>
// WebGL engine's shadow lookup, percentage-closer filtering in its unrolled
// fallback (the variant kept for the deferred pipeline): nine taps of the
// shadow map around the lookup point, each 1 where the receiver is nearer than
// the stored depth, averaged into a visibility in [0, 1].
precision highp float;

uniform sampler2D shadowMap;
uniform float shadowMapSize;
uniform vec3 diffuseColor;
uniform vec3 lightColor;

in vec2 shadowUv;
in float receiverDepth;
out vec4 fragColor;

float tapShadowMap(vec2 uv, float z) {
    float depth = texture(shadowMap, uv).r;
    return step(z, depth + 0.0005);
}

float pcf(vec2 uv, float z) {
    vec2 offset = vec2(1.0 / shadowMapSize);
    float shadowContrib = tapShadowMap(uv, z);
    shadowContrib += tapShadowMap(uv + vec2(offset.x, 0.0), z);
    shadowContrib += tapShadowMap(uv + vec2(offset.x, offset.y), z);
    shadowContrib += tapShadowMap(uv + vec2(-offset.x, offset.y), z);
    shadowContrib += tapShadowMap(uv + vec2(0.0, offset.y), z);
    shadowContrib += tapShadowMap(uv + vec2(-offset.x, 0.0), z);
    shadowContrib += tapShadowMap(uv + vec2(-offset.x, -offset.y), z);
    shadowContrib += tapShadowMap(uv + vec2(offset.x, -offset.y), z);
    shadowContrib += tapShadowMap(uv + vec2(0.0, -offset.y), z);
    return shadowContrib;
}

void main() {
    float<1> visibility = pcf(shadowUv, receiverDepth);
    fragColor = vec4(diffuseColor * lightColor * visibility, 1.0);
}
