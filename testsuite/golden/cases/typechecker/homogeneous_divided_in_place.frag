#version 330 core
#include <safegi/prelude.sgl>
// A shadow lookup through a helper function. `h.xyz /= h.w` (or
// `h.xyz = h.xyz / h.w`) divides a homogeneous point in place: from there h is
// plain coordinates with a stale w, which a function taking an hpoint (and
// dividing again) is refused; the coordinates of an undivided one are refused
// by a parameter that gets them without their w (unless the w is passed too).
space world;
space light_clip;
uniform projmap<world, light_clip> lightFromWorld;
uniform sampler2D shadowMap;
in point<world> P;
out vec4 c;
float lookup(vec2 uv, float depth) { return depth > texture(shadowMap, uv).r ? 0.0 : 1.0; }
float lookupDividing(vec2 xy, float z, float w) { return lookup(xy / w * 0.5 + 0.5, z / w); }
float lookupProjected(hpoint<light_clip> h) { vec3 ndc = h.xyz / h.w; return lookup(ndc.xy * 0.5 + 0.5, ndc.z); }
void main() {
    vec4 divided = lightFromWorld * vec4(P, 1.0);
    divided.xyz = divided.xyz / divided.w;
    float a = lookup(divided.xy * 0.5 + 0.5, divided.z);
    vec4 whole = lightFromWorld * vec4(P, 1.0);
    float b = lookupProjected(whole);
    vec4 twice = lightFromWorld * vec4(P, 1.0);
    twice.xyz /= twice.w;
    float d = lookupProjected(twice);
    vec4 undivided = lightFromWorld * vec4(P, 1.0);
    float e = lookup(undivided.xy * 0.5 + 0.5, undivided.z);
    float f = lookupDividing(undivided.xy, undivided.z, undivided.w);
    c = vec4(a, b, d, e + f);
}
