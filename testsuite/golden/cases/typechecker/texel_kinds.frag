#version 330 core
#include <safegi/prelude.sgl>
// A G-buffer of normals and directions: the texel's xyz keeps its kind and
// space, so their dot is a cosine, and a normal of another space is told. A
// normal read through a filtering lookup (texture()) is a blend of texels, not
// of unit length until normalize(); texelFetch reads one texel as it was stored.
space world;
space view;
uniform sampler2D<normal<world>> gbufferNormal;
uniform sampler2D<direction<world>> gbufferLight;
uniform sampler2D<direction<view>> gbufferEye;
uniform sampler2D<spectrum<radiance>> gbufferRadiance;
in vec2 uv;
out spectrum<irradiance> E;
void main() {
    vec3 n = normalize(texture(gbufferNormal, uv).xyz);
    vec3 l = texture(gbufferLight, uv).xyz;
    spectrum<radiance> Li = texture(gbufferRadiance, uv).rgb;
    E = Li * max(dot(n, l), 0.0) * float<solid_angle>(1.0);
    float wrongSpace = dot(n, texture(gbufferEye, uv).xyz);
    float<proj> stored = dot(texelFetch(gbufferNormal, ivec2(gl_FragCoord.xy), 0).xyz, l);
    float<proj> blended = dot(texture(gbufferNormal, uv).xyz, l);
}
