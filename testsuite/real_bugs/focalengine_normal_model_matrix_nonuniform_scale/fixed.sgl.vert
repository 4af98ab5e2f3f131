#version 450
#include <safegi/prelude.sgl>
// A hobby engine's vertex shader: positions go to world and clip space with
// the object's world matrix (which may scale one axis more than another);
// normals go to world space for the fragment stage's lighting.
space object;
space world;
space clip;

uniform map<object, world> worldMatrix;
uniform projmap<world, clip> viewProjection;

in point<object> vPosition;
in normal<object> vNormal;
out normal<world> fragNormal;
out point<world> fragPosition;

void main() {
    vec4 worldPos = worldMatrix * vec4(vPosition, 1.0);
    fragPosition = worldPos.xyz;
    fragNormal = normalize(mat3(transpose(inverse(worldMatrix))) * vNormal);
    gl_Position = viewProjection * worldPos;
}
