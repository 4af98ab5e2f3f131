#version 300 es
#include <safegi/prelude.sgl>
// The vertex shader of a geospatial viewer's glTF scenegraph layer: each glTF
// node's matrix carries the mesh into the scene, then the per-instance 3x3
// model matrix orients and scales the instance, and the normal goes the same
// way to the PBR fragment shader. The normal enters the node matrix with
// w = 0, so the node's translation does not move it.
precision highp float;
space object;
space scene;
space commonspace;

uniform map<object, scene> sceneModelMatrix;      // glTF node transform
uniform float sizeScale;

in point<object> POSITION;
in normal<object> NORMAL;
in mat3<scene, commonspace> instanceModelMatrix;       // per-instance orientation and scale
in vec3 instanceTranslation;

out normal<commonspace> pbr_vNormal;

void main() {
    vec3 pos = (instanceModelMatrix * (sceneModelMatrix * vec4(POSITION, 1.0)).xyz) * sizeScale + instanceTranslation;
    pbr_vNormal = instanceModelMatrix * (sceneModelMatrix * vec4(NORMAL, 1.0)).xyz;
    gl_Position = vec4(pos, 1.0);
}
