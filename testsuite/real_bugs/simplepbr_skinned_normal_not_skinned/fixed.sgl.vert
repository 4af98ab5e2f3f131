#version 330
#include <safegi/prelude.sgl>
// A small PBR pipeline's vertex shader with hardware skinning: the vertex is
// posed by its joint's transform before the model-view matrix; the normal
// must be posed by the same joint transform before the normal matrix, or the
// lighting stays "baked" into the bind pose.
space bind_pose;
space model;
space view;
space clip;

uniform rigidmap<bind_pose, model> p3d_TransformTable[100];   // joint transforms
uniform map<model, view> p3d_ModelViewMatrix;
uniform projmap<view, clip> p3d_ProjectionMatrix;
uniform mat3<model, view, normal> p3d_NormalMatrix;

in point<bind_pose> p3d_Vertex;
in normal<bind_pose> p3d_Normal;
in uvec4 transform_index;                 // one joint per vertex here
out point<view> v_position;
out normal<view> v_normal;

void main() {
    rigidmap<bind_pose, model> skin = p3d_TransformTable[transform_index.x];
    vec4 modelPos = skin * vec4(p3d_Vertex, 1.0);
    vec4 viewPos = p3d_ModelViewMatrix * modelPos;
    v_position = viewPos.xyz;
    v_normal = normalize(p3d_NormalMatrix * (skin * vec4(p3d_Normal, 0.0)).xyz);
    gl_Position = p3d_ProjectionMatrix * viewPos;
}
