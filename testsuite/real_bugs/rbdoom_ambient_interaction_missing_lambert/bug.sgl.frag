#version 330 core
#include <safegi/prelude.sgl>
// A Doom 3 BFG engine fork's light interaction for 'ambient' (outdoor) lights:
// the light projects its colour like any other light, so the diffuse term is
// the surface albedo / pi, times the light's irradiance on a surface facing
// it, times the Lambert cosine of the bump-mapped normal with the light vector.
space tangent_s;

const float PI = 3.14159265;

uniform sampler2D samp_bump;                        // tangent-space normal map, [0, 1] encoded
uniform sampler2D<spectrum<1>> samp_diffuse;        // albedo
uniform spectrum<irradiance / proj> lightColor;     // irradiance at normal incidence

in vec2 texcoord;
in vector<tangent_s, away> lightVector;             // toward the light
out vec4 fragColor;

void main() {
    normal<tangent_s> localNormal = normalize(normal<tangent_s>(texture(samp_bump, texcoord).xyz * 2.0 - 1.0));
    vec3 lightDir = normalize(lightVector);
    float lambert = max(dot(localNormal, lightDir), 0.0);
    vec3 albedo = texture(samp_diffuse, texcoord).rgb;
    spectrum<radiance> color = albedo / PI * lightColor;
    fragColor = vec4(color, 1.0);
}
