#version 450
#include <safegi/prelude.sgl>
// A decal generator, written as a vertex shader: each vertex of the base mesh
// under the decal goes to world space with the mesh's world matrix, gets
// texture coordinates from its position in the decal projector's box, and
// keeps a world-space normal for lighting the decal.
space object;
space world;
space decal;
space clip;

uniform map<object, world> meshMatrixWorld;
uniform mat3<object, world, normal> meshNormalMatrix;
uniform map<world, decal> worldToDecal;
uniform projmap<world, clip> viewProj;

in point<object> position;
in normal<object> normal;
out normal<world> decalNormal;
out vec2 decalUv;

void main() {
    vec4 worldPos = meshMatrixWorld * vec4(position, 1.0);
    vec3 inBox = (worldToDecal * worldPos).xyz;
    decalUv = inBox.xy + 0.5;
    decalNormal = normalize(normal);
    gl_Position = viewProj * worldPos;
}
