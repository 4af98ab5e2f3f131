#version 330 core
#include <safegi/prelude.sgl>
// An engine's steep parallax mapping: the view direction is in tangent space,
// so the layer count is chosen from its angle to the tangent-space normal
// (0, 0, 1), not to the world-space normal.
space world;
space tangent;

uniform sampler2D heightTexture;
uniform sampler2D diffuseTexture;
uniform float<1> parallaxScale;

in vec2 texCoord;
in normal<world> worldNormal;
in vector<tangent, away> tangentViewVector;          // from the fragment to the eye
out vec4 FragColor;

vec2 parallaxMapping(vec2 uv, direction<tangent, away> viewDir, float numLayers) {
    float layerDepth = 1.0 / numLayers;
    vec2 deltaUv = viewDir.xy / viewDir.z * parallaxScale / numLayers;
    float currentDepth = 0.0;
    float mapDepth = 1.0 - texture(heightTexture, uv).r;
    for (int i = 0; i < 64 && currentDepth < mapDepth; ++i) {
        uv -= deltaUv;
        mapDepth = 1.0 - texture(heightTexture, uv).r;
        currentDepth += layerDepth;
    }
    return uv;
}

void main() {
    vec3 viewDir = normalize(tangentViewVector);
    vec3 tangentNormal = normal<tangent>(0.0, 0.0, 1.0);
    float numLayers = mix(32.0, 8.0, abs(dot(worldNormal, viewDir)));
    vec2 uv = parallaxMapping(texCoord, viewDir, numLayers);
    FragColor = texture(diffuseTexture, uv);
}
