#version 330 core
#include <safegi/prelude.sgl>
// Game engine's vertex-lit world surfaces with normal maps, fragment stage: the
// normal-map texel (tangent space) is carried to world space by the frame of
// the interpolated tangent, binormal and normal, then lit by the light
// direction interpolated from the vertices.
space world;
space tangent;

uniform sampler2D u_NormalMap;

in vec2 var_TexCoords;
in vec4 var_Color;
in direction<world> var_Tangent;
in direction<world> var_Binormal;
in normal<world> var_Normal;
in direction<world, away> var_LightDir;      // toward the light
out vec4 outputColor;

void main() {
    mat3<tangent, world, rigid> tangentToWorldMatrix = mat3(var_Tangent.xyz, var_Binormal.xyz, var_Normal.xyz);
    normal<tangent> texNormal = normal<tangent>(texture(u_NormalMap, var_TexCoords).xyz * 2.0 - 1.0);
    vec3 N = normalize(tangentToWorldMatrix * texNormal);
    float NdotL = clamp(dot(N, var_LightDir), 0.0, 1.0);
    outputColor = vec4(var_Color.rgb * NdotL, var_Color.a);
}
