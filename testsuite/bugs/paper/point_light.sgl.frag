#version 330 core
#include <safegi/prelude.sgl>
// The paper's point-light direct illumination with a shadow map.
space world_s;
space light_s;
space clip_s;

uniform point<world_s> lightPos;
uniform spectrum<intensity> lightI;
uniform rigidmap<world_s, light_s> lightFromWorld;
uniform projmap<light_s, clip_s> clipFromLight;
uniform sampler2D<float<length>> shadowMap;
uniform spectrum<brdf> Kd;

in point<world_s> P;
in normal<world_s> N;
out vec4 fragColor;

void main() {
    point<light_s> pl = lightFromWorld * P;
    hpoint<clip_s> h = clipFromLight * pl;
    vec2 uv = h.xy / h.w * 0.5 + 0.5;
    float<length> stored = texture(shadowMap, uv).r;
    float visibility = -pl.z <= stored + 0.01 * meter ? 1.0 : 0.0;

    vector<world_s> toLight = lightPos - P;
    float<length> d = length(toLight);
    direction<world_s> wi = normalize(toLight);
    float<proj> cosTheta = max(dot(normalize(N), wi), 0.0);
    float<solid_angle / (area * proj)> falloff = float<solid_angle / (area * proj)>(1.0 / (d * d));
    spectrum<radiance> L = Kd * lightI * cosTheta * falloff * visibility;
    fragColor = vec4(L, 1.0);
}
