#version 450
#include <safegi/prelude.sgl>
// A node-graph material: a tangent-space normal from a texture is converted
// to world space through the tangent frame (columns T, B, N in world space)
// and lit.
space world;
space tangent;

uniform sampler2D normalMap;
uniform direction<world, toward> lightDir;
uniform spectrum<irradiance / proj> lightIrradiance;
uniform spectrum<brdf> albedo;

in normal<world> normalWS;
in direction<world> tangentWS;
in direction<world> bitangentWS;
in vec2 uv;
out vec4 fragColor;

void main() {
    mat3<tangent, world, rigid> tbn = mat3(normalize(tangentWS), normalize(bitangentWS), normalize(normalWS));
    normal<tangent> nTS = normalize(texture(normalMap, uv).xyz * 2.0 - 1.0);
    vec3 nWS = normalize(transpose(tbn) * nTS);
    float cosL = max(dot(nWS, lightDir), 0.0);
    fragColor = vec4(albedo * lightIrradiance * cosL, 1.0);
}
