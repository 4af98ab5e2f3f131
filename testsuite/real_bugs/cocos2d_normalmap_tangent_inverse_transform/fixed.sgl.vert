#version 330 core
#include <safegi/prelude.sgl>
// A 2D framework's normal-mapped sprite lighting: the sprite's local tangent
// (its x axis) and normal (out of the screen) are carried to world space by
// the node's transform, so a rotated or skewed sprite is lit from where the
// light really is.
space object;
space world;
space clip;

uniform map<object, world> u_NodeToWorld;
uniform projmap<world, clip> u_WorldToClip;
uniform vector<object> u_LocalTangent;          // (1, 0, 0)

in point<object> a_position;
out vector<world> v_tangent;
out point<world> v_worldPos;

void main() {
    vec4 worldPos = u_NodeToWorld * vec4(a_position, 1.0);
    v_worldPos = worldPos.xyz;
    v_tangent = (u_NodeToWorld * vec4(u_LocalTangent, 0.0)).xyz;
    gl_Position = u_WorldToClip * worldPos;
}
