#version 450
#include <safegi/prelude.sgl>
// An engine's terrain vertex shader: heights come from a heightmap; the
// tangent and bitangent are the central differences along the grid's two
// axes, and the normal is perpendicular to both.
space world;
space clip;

uniform sampler2D heightmap;
uniform float<length> heightScale;
uniform float<length> sampleSpacing;
uniform vec2 uvStep;
uniform projmap<world, clip> viewProj;

in point<world> position;
in vec2 uv;
out normal<world> worldNormal;

float<length> getHeight(vec2 at) {
    return texture(heightmap, at).r * heightScale;
}

void main() {
    float up = getHeight(uv - vec2(0.0, uvStep.y));
    float down = getHeight(uv + vec2(0.0, uvStep.y));
    float left = getHeight(uv - vec2(uvStep.x, 0.0));
    float right = getHeight(uv + vec2(uvStep.x, 0.0));
    vec3 bitangent = normalize(vec3(0.0, 2.0 * sampleSpacing, down - up));
    vec3 tangent = normalize(vec3(2.0 * sampleSpacing, 0.0, right - left));
    worldNormal = normalize(cross(tangent, bitangent));
    gl_Position = viewProj * vec4(position, 1.0);
}
