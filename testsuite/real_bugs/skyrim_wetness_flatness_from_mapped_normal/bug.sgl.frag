#version 450
#include <safegi/prelude.sgl>
// Rain wetness: how much water a surface holds, and whether puddles form,
// depends on how flat the geometry is, read from the interpolated vertex
// normal (world z is up). The normal-mapped shading normal describes the
// small bumps of the texture, not the slope water runs off; it is blended
// toward the flat puddle normal only where a puddle forms.
space world;

uniform float minWetnessValue;
uniform float puddleWetness;

in normal<world> vVertexNormal;      // geometric, interpolated
in normal<world> vWorldNormal;       // after normal mapping
in float vRainMask;
out vec4 fragNormalWetness;

void main() {
    normal<world> vertexNormal = normalize(vVertexNormal);
    normal<world> worldNormal = normalize(vWorldNormal);
    float flatness = clamp(max(minWetnessValue, worldNormal.z), 0.0, 1.0);
    float wetness = vRainMask * flatness;
    float puddle = clamp((wetness - puddleWetness) / (1.0 - puddleWetness), 0.0, 1.0);
    vec3 wetnessNormal = normalize(mix(vec3(worldNormal), vec3(vertexNormal), puddle));
    fragNormalWetness = vec4(wetnessNormal * 0.5 + 0.5, wetness);
}
