#version 330 core
#include <safegi/prelude.sgl>
// A Direct3D 9 translation layer's fixed-function texture-coordinate
// generation, camera-space reflection vector mode: the cube-map coordinate
// is the mirror direction about the camera-space normal of the ray from the
// eye to the vertex.
space object;
space view : eye;
space clip;

uniform map<object, view> worldView;
uniform mat3<object, view, normal> normalMatrix;
uniform projmap<view, clip> projection;

in point<object, shaded> inPosition;
in normal<object> inNormal;
out direction<view, away> texCoordCube;

void main() {
    vec3 posEye = (worldView * vec4(inPosition, 1.0)).xyz;
    vec3 n = normalize(normalMatrix * inNormal);
    vec3 E_tci = normalize(posEye);
    texCoordCube = 2.0 * n * dot(n, E_tci) - E_tci;
    gl_Position = projection * vec4(posEye, 1.0);
}
