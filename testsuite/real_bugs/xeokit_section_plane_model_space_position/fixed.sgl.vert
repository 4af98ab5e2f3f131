#version 300 es
#include <safegi/prelude.sgl>
// A BIM viewer's batched-model vertex shader: positions are decoded to the
// model's coordinates and placed in the world by the model's world matrix;
// the fragment shader slices against section planes given in world space,
// so it receives the world-space position.
precision highp float;
space quantized;
space model;
space world;
space view;
space clip;

uniform map<quantized, model> positionsDecodeMatrix;
uniform map<model, world> worldMatrix;
uniform map<world, view> viewMatrix;
uniform projmap<view, clip> projMatrix;

in point<quantized> position;
out point<world> vWorldPosition;                  // sliced by the section planes

void main() {
    vec4 modelPosition = positionsDecodeMatrix * vec4(position, 1.0);
    vec4 worldPosition = worldMatrix * modelPosition;
    vWorldPosition = worldPosition.xyz;
    gl_Position = projMatrix * (viewMatrix * worldPosition);
}
