#version 300 es
precision mediump float;
#include <safegi/prelude.sgl>
// A game-level viewer's port of a platformer's lighting (per vertex): each
// directional light's direction is the forward axis of the light's transform,
// a column of its rotation, not the Euler angles the transform was built from.
space object_s;
space world;
space clip;
space light_s;

uniform map<object_s, world> u_ModelMatrix;
uniform projmap<world, clip> u_ViewProj;
uniform rigidmap<light_s, world> u_LightMatrix;   // the light's orientation
uniform vec3<angle> u_LightEuler;                // the angles it was built from
uniform vec4 u_LightColor;
uniform vec4 u_AmbientColor;

in point<object_s> a_Position;
in normal<object_s> a_Normal;
out vec4 v_Color;

void main() {
    vec4 worldPos = u_ModelMatrix * vec4(a_Position, 1.0);
    gl_Position = u_ViewProj * worldPos;
    vec3 n = normalize((vec4(a_Normal, 0.0) * inverse(u_ModelMatrix)).xyz);
    vec3 lightDir = u_LightEuler;          // the way the light shines
    float diffuse = max(dot(n, -lightDir), 0.0);
    v_Color = u_AmbientColor + u_LightColor * diffuse;
}
