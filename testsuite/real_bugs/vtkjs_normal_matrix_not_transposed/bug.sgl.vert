#version 300 es
#include <safegi/prelude.sgl>
// A web visualisation toolkit's volume renderer: gradient normals are
// computed in world coordinates and shaded in view coordinates, so the
// "key" normal matrix is the inverse transpose of the world-to-view matrix.
precision highp float;
space world;
space view;
space clip;

uniform map<world, view> WCVCMatrix;
uniform projmap<view, clip> VCPCMatrix;

in point<world> vertexWC;
in normal<world> gradientWC;
out normal<view> normalVC;

void main() {
    mat3 normalMatrix = inverse(mat3(WCVCMatrix));
    normalVC = normalize(normalMatrix * gradientWC);
    gl_Position = VCPCMatrix * WCVCMatrix * vec4(vertexWC, 1.0);
}
