#version 330 core
#include <safegi/prelude.sgl>
// An engine's PBS vertex shader works in view space: the position goes
// through the world-view matrix, and the normal through the inverse transpose
// of its upper 3x3, so that a mesh stretched along one axis keeps normals
// perpendicular to its surface.
space object;
space view;
space clip;

uniform map<object, view> worldViewMat;
uniform projmap<view, clip> projectionMat;

in point<object> vertexPos;
in normal<object> vertexNormal;
out point<view> outPos;
out normal<view> outNormal;

void main() {
    outPos = (worldViewMat * vec4(vertexPos, 1.0)).xyz;
    outNormal = mat3(worldViewMat) * vertexNormal;
    gl_Position = projectionMat * vec4(outPos, 1.0);
}
