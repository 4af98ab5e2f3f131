#version 330 core
#include <safegi/prelude.sgl>
// Normal mapping in a PBR lighting shader: the tangent-space texel is taken to
// world space by the per-fragment tangent frame, and the result normalized.
space world;

uniform sampler2D m_NormalMap;
uniform direction<world> lightDir;                       // toward the light
uniform spectrum<irradiance / proj> lightColor;
uniform spectrum<1> albedo;

in normal<world> wNormal;
in vec4 wTangent;
in vec2 texCoord;
out vec4 fragColor;

const float PI = 3.14159265358979;

void main() {
    vec3 normalHeight = texture(m_NormalMap, texCoord).xyz * 2.0 - 1.0;
    vec3 N = normalize(wNormal);
    vec3 T = normalize(wTangent.xyz);
    vec3 B = cross(N, T) * wTangent.w;
    mat3 tbnMat = mat3(T, B, N);
    vec3 normal = tbnMat * normalHeight;
    float NdotL = max(dot(normal, lightDir), 0.0);
    spectrum<radiance> color = albedo / PI * lightColor * NdotL;
    fragColor = vec4(color, 1.0);
}
