#version 330 core
#include <safegi/prelude.sgl>
// A sky box drawn around the camera with the view rotation only: its
// vertices' normals are directions in world space. The sky's own rotation
// (its world matrix) turns the cube map, so a world direction is looked up
// in the sky's frame through the inverse of that matrix.
space world;
space view;
space clip;
space sky;

uniform rigidmap<sky, world> g_WorldMatrix;
uniform rigidmap<world, sky> g_WorldMatrixInverse;
uniform rigidmap<world, view> g_ViewMatrix;
uniform projmap<view, clip> g_ProjectionMatrix;
uniform float m_NormalScale;

in vector<world> inPosition;
in vector<world> inNormal;
out vector<sky> direction;

void main() {
    vec3 viewDir = (g_ViewMatrix * vec4(inPosition, 0.0)).xyz;   // rotation only
    gl_Position = g_ProjectionMatrix * vec4(viewDir, 1.0);        // the sky at that offset from the eye
    vec4 normal = vec4(inNormal * m_NormalScale, 0.0);
    direction = (g_WorldMatrixInverse * normal).xyz;
}
