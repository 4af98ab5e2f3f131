#version 450
#include <safegi/prelude.sgl>
// A Vulkan sample's reflective object lit by a cube map array (its HLSL
// port): the incident ray is the eye's ray to the shaded point (view space
// has the eye at its origin), reflected about the normal and carried back to
// the object's space for the lookup; a point light adds Phong shading.
space object;
space view : eye;

layout(binding = 0) uniform UBO {
    map<view, object> invModel;
    float lodBias;
    int cubeMapIndex;
} ubo;
layout(binding = 1) uniform samplerCubeArray samplerCubeMapArray;

layout(location = 0) in point<view, shaded> inPos;
layout(location = 1) in normal<view> inNormal;
layout(location = 3) in vector<view, away> inViewVec;
layout(location = 4) in vector<view, away> inLightVec;
layout(location = 0) out vec4 outFragColor;

void main() {
    vec3 cI = normalize(inViewVec);
    vec3 cR = reflect(cI, normalize(inNormal));

    cR = vec3(ubo.invModel * vec4(cR, 0.0));
    cR *= vec3(1.0, -1.0, -1.0);

    vec4 color = textureLod(samplerCubeMapArray, vec4(cR, float(ubo.cubeMapIndex)), ubo.lodBias);

    vec3 N = normalize(inNormal);
    vec3 L = normalize(inLightVec);
    vec3 V = normalize(inViewVec);
    vec3 R = reflect(-L, N);
    vec3 ambient = vec3(0.5) * color.rgb;
    vec3 diffuse = max(dot(N, L), 0.0) * vec3(1.0);
    vec3 specular = pow(max(dot(R, V), 0.0), 16.0) * vec3(0.5);
    outFragColor = vec4(ambient + diffuse * color.rgb + specular, 1.0);
}
