#version 330 core
#include <safegi/prelude.sgl>
// A voxel game's chunk shader, parallax mapping: the tangent frame is built per
// pixel from screen-space derivatives of the view-space position and of the
// texture coordinates (tangent and bitangent: the view-space change per unit of
// u and v; third axis the normal). The eye vector is carried into that frame by
// the frame's transpose, and the texture coordinate is shifted along its
// tangent-plane part by the sampled height.
space view : eye;
space tangent;

uniform sampler2D textureAtlasHeight;
uniform float parallaxScale;
uniform float parallaxBias;

in point<view, shaded> vertexViewPos;
in normal<view> normal;
in vec2 texCoord0;
out vec4 fragColor;

const float TEXTURE_OFFSET = 0.000244140625;

void main() {
    vec3 normalizedVPos = -normalize(vertexViewPos);
    mat2x3 screenToView = mat2x3(dFdx(vertexViewPos), dFdy(vertexViewPos));
    mat2 screenToUv = mat2(dFdx(texCoord0), dFdy(texCoord0));
    mat2x3 uvToView = screenToView * inverse(screenToUv);
    mat3<tangent, view> tbn = mat3(uvToView[0], uvToView[1], normalize(normal));

    vec3 eyeTangentSpace = tbn * vertexViewPos;
    vec2 texCoord = texCoord0;
    float height = parallaxScale * texture(textureAtlasHeight, texCoord).r - parallaxBias;
    texCoord += height * eyeTangentSpace.xy / eyeTangentSpace.z * TEXTURE_OFFSET;
    fragColor = vec4(texCoord, 0.0, 1.0);
}
