#version 330 core
#include <safegi/prelude.sgl>
// A render pipeline's shader-graph inputs: the object-space normal a graph
// reads is the world-space normal carried back by the model matrix
// (multiplied from the left, the transpose of the inverse of the inverse),
// which a scaled object stretches, so it is normalized before the graph uses it.
space object;
space world;

uniform map<object, world> UNITY_MATRIX_M;
uniform direction<object> graphLightDirOS;    // a graph input in object space

in normal<world> worldSpaceNormalInterp;
out vec4 fragColor;

void main() {
    vec3 worldSpaceNormal = normalize(worldSpaceNormalInterp);
    vec3 objectSpaceNormal = normalize(worldSpaceNormal * mat3(UNITY_MATRIX_M));
    float ndotl = clamp(dot(objectSpaceNormal, graphLightDirOS), 0.0, 1.0);
    fragColor = vec4(vec3(ndotl), 1.0);
}
