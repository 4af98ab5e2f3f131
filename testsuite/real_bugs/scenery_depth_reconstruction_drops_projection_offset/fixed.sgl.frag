#version 450
#include <safegi/prelude.sgl>
// A deferred renderer reconstructs the view-space position from the depth
// buffer with the inverse projection, written out element by element: x and
// y need the inverse projection's translation terms too (an off-axis, e.g.
// stereo, projection has them), not only its diagonal.
space view : eye;
space world;

uniform sampler2D depthTex;                 // window depth in [0, 1]
uniform mat4 invProjection;                 // used element by element
uniform map<view, world> invView;

in vec2 texcoord;
out vec4 fragWorldPosDist;

vec3 viewFromDepth(float depth, vec2 uv) {
    vec3 clipSpacePosition = vec3(uv * 2.0 - 1.0, depth * 2.0 - 1.0);
    vec4 viewSpacePosition = vec4(
        invProjection[0][0] * clipSpacePosition.x + invProjection[3][0],
        invProjection[1][1] * clipSpacePosition.y + invProjection[3][1],
        -1.0,
        invProjection[2][3] * clipSpacePosition.z + invProjection[3][3]);
    viewSpacePosition /= viewSpacePosition.w;
    return viewSpacePosition.xyz;
}

void main() {
    float depth = texture(depthTex, texcoord).r;
    point<view> P = point<view>(viewFromDepth(depth, texcoord));
    vec4 world = invView * vec4(P, 1.0);
    float<length> dist = length(P);
    fragWorldPosDist = vec4(world.xyz, dist);
}
