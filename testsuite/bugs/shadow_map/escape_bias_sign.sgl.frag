#version 330 core
#include <safegi/prelude.sgl>
// Shadow map lookup: the texels are depths along the light's axis, in length.
space world;
space light_s;
space clip;

uniform rigidmap<world, light_s> lightFromWorld;
uniform projmap<light_s, clip> clipFromLight;
uniform sampler2D<float<length>> shadowMap;

in point<world> P;
out vec4 fragColor;

void main() {
    point<light_s> pl = lightFromWorld * P;
    hpoint<clip> h = clipFromLight * pl;
    vec2 uv = h.xy / h.w * 0.5 + 0.5;
    float<length> depthToLight = -pl.z;
    float<length> stored = texture(shadowMap, uv).r;
    float<length> bias = 0.05 * meter;
    bool lit = depthToLight + bias <= stored;
    fragColor = vec4(vec3(lit ? 1.0 : 0.0), 1.0);
}
