#version 330 core
// Shadow-map visibility (the paper's shadow map shader): the shading point is
// carried into the light's clip space, divided by w, and its distance to the
// light compared with the depth the map stores, in length units.
#include <safegi/prelude.sgl>

space world;
space light_s;
space light_clip;

uniform rigidmap<world, light_s>       lightFromWorld;
uniform projmap<light_s, light_clip>   clipFromLight;
uniform sampler2D<float<length>>       shadowMap;
uniform float<length>                  bias;
uniform spectrum<radiance>             Lshade;

in point<world> P;

out vec4 fragColor;

void main() {
    point<light_s> Pl = lightFromWorld * P;
    hpoint<light_clip> h = clipFromLight * Pl;
    point<light_clip> ndc = homogenize(h);
    vec2 uv = ndc.xy / meter * 0.5 + 0.5;        // NDC to texture coordinates
    float<length> stored = texture(shadowMap, uv).r;
    float<length> dist = length(Pl - point<light_s>(0.0));
    float<1> visible = dist - bias > stored ? 0.0 : 1.0;
    fragColor = vec4(Lshade * visible, 1.0);
}
