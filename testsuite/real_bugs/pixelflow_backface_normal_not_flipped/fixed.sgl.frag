#version 330 core
#include <safegi/prelude.sgl>
// A creative-coding library's sky-light renderer, geometry-buffer pass: it
// stores the eye-space normal and the fragment's depth. Surfaces are drawn
// double-sided, so a fragment of a back face gets the normal of the side it
// shows, the vertex normal flipped.
space object;
space view : eye;

uniform mat3<object, view, normal> normalMatrix;

in normal<object> vertNormal;
out vec4 fragColor;

void main() {
    vec3 vert_normal = normalize(normalMatrix * vertNormal);
    if (!gl_FrontFacing) vert_normal = -vert_normal;
    fragColor = vec4(vert_normal, 1.0 / gl_FragCoord.w);
}
