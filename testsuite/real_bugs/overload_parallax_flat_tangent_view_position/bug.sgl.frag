#version 450
#include <safegi/prelude.sgl>
// Parallax mapping in tangent space: the vertex shader carries the camera
// position and the vertex position to the triangle's tangent space; both
// are interpolated, and their difference gives the per-fragment view
// direction that offsets the texture coordinates. An input qualified `flat`
// would take the provoking vertex's value for the whole triangle.
space tangent_s;

uniform sampler2D heightMap;
uniform sampler2D albedoMap;
uniform float heightScale;

flat in point<tangent_s> vTangentViewPos;
in point<tangent_s, shaded> vTangentFragPos;
in vec2 vTexCoords;
out vec4 fragColor;

void main() {
    direction<tangent_s, away> viewDir = normalize(vTangentViewPos - vTangentFragPos);
    float height = texture(heightMap, vTexCoords).r;
    vec2 p = viewDir.xy / viewDir.z * (height * heightScale);
    vec2 uv = vTexCoords - p;
    fragColor = vec4(texture(albedoMap, uv).rgb, 1.0);
}
