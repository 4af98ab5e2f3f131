#version 330 core
#include <safegi/prelude.sgl>
// Image-based lighting of a small PBR engine: diffuse from an irradiance cube
// map through the Lambert BRDF, specular from a prefiltered radiance cube map
// and a split-sum lookup table.
space world;

uniform samplerCube<spectrum<irradiance>, world> irradianceMap;
uniform samplerCube<spectrum<radiance>, world> prefilterMap;
uniform sampler2D brdfLUT;
uniform point<world> camPos;
uniform spectrum<1> albedo;
uniform float<1> roughness;

in point<world, shaded> P;
in normal<world> vNormal;
out vec4 fragColor;

const float PI = 3.14159265;

void main() {
    vec3 N = normalize(vNormal);
    vec3 V = normalize(camPos - P);
    vec3 R = reflect(-V, N);
    float NdotV = max(dot(N, V), 0.0);
    vec3 irradiance = texture(irradianceMap, N).rgb;
    spectrum<radiance> diffuse = albedo / PI * irradiance;
    vec3 prefiltered = textureLod(prefilterMap, R, roughness * 4.0).rgb;
    vec2 envBRDF = texture(brdfLUT, vec2(NdotV, roughness)).rg;
    vec3 specular = prefiltered * (0.04 * envBRDF.x + envBRDF.y);
    spectrum<radiance> ambient = (diffuse + specular) * 2.0;
    fragColor = vec4(ambient, 1.0);
}
