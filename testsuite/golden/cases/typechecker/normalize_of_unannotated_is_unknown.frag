#version 330 core
#include <safegi/prelude.sgl>
// normalize() of an unannotated vector is of unit length, but it may be a normal
// as well as a direction: its cosine with a direction is as unknown as the
// vector was (a tangent frame built of plain vectors, as in a normal-mapping
// shader), not a plain number. A vec4 of a vector with w = 0 normalizes to a
// direction with w = 0: a direction, not a vector, where a length is needed.
space world;
space view;
uniform direction<world> lightDir;
uniform spectrum<irradiance / proj> lightColor;
uniform spectrum<brdf> diffuse;
uniform map<world, view> view;
uniform point<world> lightPosition;
in normal<world> wNormal;
in vec4 wTangent;
in vec3 texel;
in point<world> P;
out vec4 fragColor;
out vector<view> toLightView;
void main() {
    vec3 N = normalize(wNormal);
    vec3 T = normalize(wTangent.xyz);
    mat3 tbn = mat3(T, cross(N, T) * wTangent.w, N);
    vec3 n = normalize(tbn * texel);
    spectrum<radiance> L = diffuse * lightColor * max(dot(n, lightDir), 0.0);
    float<1> plainCosine = dot(normalize(texel), lightDir);
    vec4 toLight = view * vec4(lightPosition, 1.0) - view * vec4(P, 1.0);
    toLightView = toLight.xyz;
    toLightView = normalize(toLight).xyz;
    fragColor = vec4(L, 1.0);
}
