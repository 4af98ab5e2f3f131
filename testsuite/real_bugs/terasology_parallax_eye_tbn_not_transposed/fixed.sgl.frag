#version 330 core
#include <safegi/prelude.sgl>
// A voxel game's chunk shader, parallax mapping: the tangent frame's columns
// are the face's tangent, bitangent and normal in view space, so it carries
// tangent space to view space; the eye vector goes the other way, from view
// space into tangent space, by the frame's transpose (v * tbn). The height map
// then shifts the texture coordinate along the eye vector's tangent-space xy.
space view : eye;
space tangent_s;

uniform sampler2D textureAtlas;
uniform sampler2D textureAtlasHeight;
uniform float<1> parallaxScale;
uniform float<1> parallaxBias;
uniform float TEXTURE_OFFSET;

in point<view, shaded> vertexViewPos;
in direction<view> vTangent;
in direction<view> vBitangent;
in normal<view> vNormal;
in vec2 vTexCoord;
out vec4 fragColor;

void main() {
    mat3<tangent_s, view, rigid> tbn = mat3(normalize(vTangent), normalize(vBitangent), normalize(vNormal));
    vec3 normalizedVPos = normalize(vertexViewPos);
    vec3 eyeTangentSpace = normalizedVPos * tbn;
    float height = parallaxScale * texture(textureAtlasHeight, vTexCoord).r - parallaxBias;
    vec2 texCoord = vTexCoord + height * eyeTangentSpace.xy * TEXTURE_OFFSET;
    fragColor = texture(textureAtlas, texCoord);
}
