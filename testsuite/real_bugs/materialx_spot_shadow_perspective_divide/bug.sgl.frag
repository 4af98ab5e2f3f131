#version 400
#include <safegi/prelude.sgl>
// A material library's generated GLSL: the shadow of a spot light is looked
// up at the shaded point's position in the light's clip space, divided by w
// (a spot light's projection is perspective) and moved from [-1, 1] to [0, 1].
space world;
space light_clip;

uniform projmap<world, light_clip> u_shadowMatrix;
uniform sampler2D u_shadowMap;

in point<world> positionWorld;
out vec4 fragColor;

float shadowOcclusion(sampler2D shadowMap, vec2 uv, float depth)
{
    float stored = texture(shadowMap, uv).r;
    return depth > stored + 0.001 ? 0.0 : 1.0;
}

void main()
{
    vec4 shadowCoord = u_shadowMatrix * vec4(positionWorld, 1.0);
    vec3 coord = shadowCoord.xyz * 0.5 + 0.5;
    float occlusion = shadowOcclusion(u_shadowMap, coord.xy, coord.z);
    fragColor = vec4(vec3(occlusion), 1.0);
}
