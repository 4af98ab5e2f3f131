#version 450
#include <safegi/prelude.sgl>
// A hobby engine's forward shading with a normal map: the normal read from
// the map is in the surface's tangent space and is carried to world space by
// the tangent frame before it meets the light direction.
space world;
space tangent;

layout(binding = 0) uniform sampler2D normalMap;
layout(binding = 1) uniform LightData {
    direction<world> toSun;
    spectrum<irradiance / proj> sunColor;   // on a surface facing the sun
};
layout(binding = 2) uniform sampler2D baseColorMap;

layout(location = 0) in normal<world> inNormal;
layout(location = 1) in vector<world> inTangent;
layout(location = 2) in vector<world> inBitangent;
layout(location = 3) in vec2 inUV;
layout(location = 0) out vec4 outColor;

const float<brdf> INV_PI = float<brdf>(0.3183098861837907);

void main() {
    normal<tangent> mapNormal = normal<tangent>(texture(normalMap, inUV).xyz * 2.0 - 1.0);
    mat3<tangent, world, rigid> TBN = mat3(normalize(inTangent), normalize(inBitangent), normalize(inNormal));
    vec3 N = normalize(mapNormal);
    float NdotL = max(dot(N, toSun), 0.0);
    vec3 albedo = texture(baseColorMap, inUV).rgb;
    spectrum<radiance> L = albedo * INV_PI * sunColor * NdotL;
    outColor = vec4(L, 1.0);
}
