#version 330 core
#include <safegi/prelude.sgl>
// A node-based shader editor's Transform node, direction mode, view to world:
// a direction is carried by the inverse view matrix with w = 0, so the
// camera's translation does not move it, and renormalized.
space world;
space view;

uniform map<view, world> UNITY_MATRIX_I_V;
uniform samplerCube<spectrum<radiance>, world> environment;

in direction<view> viewSpaceDirection;
out vec4 fragColor;

void main() {
    vec3 worldDir = normalize((UNITY_MATRIX_I_V * vec4(viewSpaceDirection, 1.0)).xyz);
    spectrum<radiance> L = texture(environment, worldDir).rgb;
    fragColor = vec4(L, 1.0);
}
