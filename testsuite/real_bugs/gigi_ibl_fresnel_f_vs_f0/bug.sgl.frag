#version 330 core
#include <safegi/prelude.sgl>
// A technique library's split-sum image-based specular: the prefiltered
// radiance is scaled by F0 * A + B from the environment BRDF table, whose
// integral already contains the Fresnel term; F (evaluated at N.V) applies it
// twice.
space world;

uniform samplerCube<spectrum<radiance>> prefilteredEnv;
uniform samplerCube<spectrum<radiance>> irradianceMap;    // cosine-convolved (E / pi)
uniform sampler2D brdfLut;
uniform point<world> cameraPos;
uniform spectrum<1> F0;
uniform spectrum<1> albedo;
uniform float<1> roughness;

in point<world, shaded> worldPos;
in normal<world> worldNormal;
out vec4 fragColor;

void main() {
    vec3 N = normalize(worldNormal);
    vec3 V = normalize(cameraPos - worldPos);
    vec3 R = reflect(-V, N);
    float NdotV = max(dot(N, V), 0.0);
    vec3 F = F0 + (1.0 - F0) * pow(1.0 - NdotV, 5.0);
    vec3 prefilteredColor = textureLod(prefilteredEnv, R, roughness * 4.0).rgb;
    vec2 brdf = texture(brdfLut, vec2(NdotV, roughness)).rg;
    vec3 specular = prefilteredColor * (F * brdf.x + brdf.y);
    spectrum<radiance> diffuse = (1.0 - F) * albedo * texture(irradianceMap, N).rgb;
    fragColor = vec4(specular + diffuse, 1.0);
}
