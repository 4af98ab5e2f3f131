#version 330 core
#include <safegi/prelude.sgl>
// A shadow-map coordinate leaves the vertex shader: divided by w it is a
// position in the light's NDC; without the divide the fragment shader gets
// x·w, y·w, z·w with no w to undo them (a perspective light's shadow drifts).
space world;
space light_clip;
uniform projmap<world, light_clip> lightClipFromWorld;
in point<world> P;
out vec3 shadowUv;
out vec3 shadowUvUndivided;
out vec4 lightClip;          // the whole vec4 may leave: the fragment shader divides
void main() {
    vec4 h = lightClipFromWorld * P;
    shadowUv = (h.xyz / h.w) * 0.5 + 0.5;
    lightClip = h;
    shadowUvUndivided = h.xyz * 0.5 + 0.5;
    gl_Position = h;
}
