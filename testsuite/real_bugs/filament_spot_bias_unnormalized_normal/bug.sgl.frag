#version 330 core
#include <safegi/prelude.sgl>
// A spot light's shadow lookup with normal-offset bias: the receiver is moved
// along its normal by the bias before it is projected into the light's
// shadow map. The offset is a length only along a unit normal, so the
// renormalised normal is used, not the interpolated one.
space world;
space shadow_tex;

uniform projmap<world, shadow_tex> shadowFromWorld;   // light view-projection and texture bias
uniform sampler2DShadow shadowMap;
uniform float<length> normalBias;
uniform spectrum<radiance> litRadiance;

in point<world> vertex_worldPosition;
in normal<world> vertex_worldNormal;
out vec4 fragColor;

void main() {
    vec3 n = normalize(vertex_worldNormal);
    vec3 biasedPosition = vertex_worldPosition + vertex_worldNormal * normalBias;
    vec4 shadowPosition = shadowFromWorld * vec4(biasedPosition, 1.0);
    float visibility = textureProj(shadowMap, shadowPosition);
    spectrum<radiance> L = litRadiance * visibility;
    fragColor = vec4(L, 1.0);
}
