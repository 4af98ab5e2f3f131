#version 300 es
#include <safegi/prelude.sgl>
// A procedural-modelling library's default vertex shader: the host uploads a
// separate normal matrix (the inverse transpose of the model matrix's 3x3)
// next to the model matrix, and normals are carried by it.
precision highp float;
space object;
space world;
space clip;

uniform map<object, world> modelTransform;
uniform mat3<object, world, normal> normalTransform;
uniform projmap<world, clip> projectionView;

in point<object> vertexPosition;
in normal<object> vertexNormal;
out normal<world> vNormal;

void main() {
    gl_Position = projectionView * modelTransform * vec4(vertexPosition, 1.0);
    vNormal = (modelTransform * vec4(vertexNormal, 0.0)).xyz;
}
