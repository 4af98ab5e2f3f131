#version 300 es
#include <safegi/prelude.sgl>
// A game engine's GLES2-style forward shader, spot light shadow: the vertex
// in the light's clip space goes to the shadow sampler, which divides by w
// itself before the lookup; the caller hands it the homogeneous position.
precision highp float;
space view;
space light_clip;

uniform projmap<view, light_clip> light_shadow_matrix;
uniform highp sampler2D light_shadow_atlas;

in point<view> vertex;
out vec4 frag_color;

float sample_shadow(highp sampler2D shadow, hpoint<light_clip> spos) {
    vec3 pos = spos.xyz / spos.w;
    pos = pos * 0.5 + 0.5;
    float depth = texture(shadow, pos.xy).r;
    return step(pos.z, depth + 0.0005);
}

void main() {
    highp vec4 splane = light_shadow_matrix * vec4(vertex, 1.0);
    splane.xyz /= splane.w;
    float shadow = sample_shadow(light_shadow_atlas, splane);
    frag_color = vec4(vec3(shadow), 1.0);
}
