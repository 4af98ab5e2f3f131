#version 400
#include <safegi/prelude.sgl>
// A creative-coding deferred-shading add-on's directional shadow pass: a
// slope-scaled depth bias tan(theta) from the angle between the surface normal
// and the direction toward the light. The light uniform is the direction the
// light travels, so the angle is taken with its opposite, as the diffuse term
// below does.
space view : eye;

uniform sampler2DRect tex;
uniform sampler2DRect lightDepthTex;
uniform sampler2DRect<point<view>> positionTex;
uniform sampler2DRect<normal<view>> normalAndDepthTex;
uniform mat4 shadowTransMat;                              // to the light's [0, 1] depth-map coordinates
uniform direction<view, toward> lightDir;                 // the light's travel direction
uniform vec4 ambient;
uniform vec4 diffuse;
uniform float darkness;

in vec2 vTexCoord;
out vec4 outputColor;

void main() {
    vec4 read = texture(tex, vTexCoord);
    point<view> position = texture(positionTex, vTexCoord).xyz;
    vec3 normal = normalize(texture(normalAndDepthTex, vTexCoord).xyz);
    vec4 shadowCoord = shadowTransMat * vec4(position, 1.0);
    float dist = shadowCoord.z;
    float shadow = 1.0;
    vec2 res = textureSize(lightDepthTex);
    float texel = texture(lightDepthTex, shadowCoord.xy * res).r;
    float bias = 0.0005 * tan(acos(dot(normal, lightDir)));
    if (texel < dist - bias) shadow -= darkness;
    outputColor = read * ambient + read * diffuse * dot(normal, -lightDir) * shadow;
    outputColor.a = 1.0;
}
