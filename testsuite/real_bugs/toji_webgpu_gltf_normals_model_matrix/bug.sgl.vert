#version 450
#include <safegi/prelude.sgl>
// WebGPU glTF renderer samples (WGSL rewritten as GLSL): every mesh node has a
// world transform and, since the fix, a normal matrix computed on the CPU (the
// inverse transpose of the world transform's linear part); the normal goes to
// the fragment stage in view space.
space object;
space world;
space view;
space clip;

uniform projmap<view, clip> projection;
uniform rigidmap<world, view> viewMatrix;
uniform map<object, world> model;              // glTF nodes may scale non-uniformly
uniform mat3<object, world, normal> normalMat;

layout(location = 0) in point<object> inPosition;
layout(location = 1) in normal<object> inNormal;
layout(location = 0) out normal<view> vNormal;

void main() {
    gl_Position = projection * viewMatrix * model * vec4(inPosition, 1.0);
    vNormal = normalize((viewMatrix * model * vec4(inNormal, 0.0)).xyz);
}
