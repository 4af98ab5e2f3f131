#version 330 core
#include <safegi/prelude.sgl>
// Baking a node's derived transform into a mesh on import (here as a vertex
// shader over the mesh's vertices): positions take the whole transform,
// translation included; normals take the inverse transpose of its linear
// part, never the translation.
space node;
space mesh;

uniform map<node, mesh> derivedTransform;

in point<node> vertexPosition;
in normal<node> vertexNormal;
out point<mesh> bakedPosition;
out normal<mesh> bakedNormal;

void main() {
    bakedPosition = (derivedTransform * vec4(vertexPosition, 1.0)).xyz;
    mat3 normalMatrix = transpose(inverse(mat3(derivedTransform)));
    bakedNormal = normalize(normalMatrix * vertexNormal);
    gl_Position = vec4(0.0);
}
