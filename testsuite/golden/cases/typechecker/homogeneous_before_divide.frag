#version 460
#include <safegi/prelude.sgl>
// The coordinates of a homogeneous point are a position only once divided by
// its w: a primary ray's direction from the inverse projection's undivided xyz,
// the length of undivided clip coordinates, or a tangent frame built from
// their screen-space derivatives, are no quantity of the space. A plane
// equation's dot with the whole vec4 is projective and fine.
space world;
space view : eye;
space clip;

uniform projmap<clip, view> viewFromClip;
uniform vec4 frustumPlane;
uniform vec2 resolution;

in hpoint<clip> clipPosition;
out vec4 color;

void main() {
    vec2 ndc = gl_FragCoord.xy / resolution * 2.0 - 1.0;
    hpoint<view> target = viewFromClip * vec4(ndc, 1.0, 1.0);
    vec3 ray = normalize(target.xyz / target.w);
    float inside = dot(frustumPlane, clipPosition);

    vec3 wrongRay = normalize(target.xyz);
    float depth = length(clipPosition.xyz);
    vec3 slope = dFdx(clipPosition.xyz);
    color = vec4(ray + wrongRay + slope, inside + depth);
}
