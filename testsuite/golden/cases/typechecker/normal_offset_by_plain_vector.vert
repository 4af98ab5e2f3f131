#version 330 core
#include <safegi/prelude.sgl>
// A normal offset by an unannotated vector (a morph target's delta) is still a
// normal of its space, no longer of unit length: normalize() makes it the
// morphed normal; used as it is where its length matters, it is refused.
space object;
uniform direction<object> toLight;
uniform float weight;
in normal<object> baseNormal;
in vec3 normalDelta;
out normal<object> morphed;
out float shade;
void main() {
    morphed = normalize(baseNormal + normalDelta * weight);
    shade = max(dot(baseNormal + normalDelta * weight, toLight), 0.0);
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
