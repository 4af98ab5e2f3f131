#version 450
#include <safegi/prelude.sgl>
// deck.gl's "common" space: a word GLSL reserves may name a space, as the
// annotations are erased before a driver sees them; it is checked like any
// other space (a reserved word is still refused as a variable's name).
space common;
space world;

uniform map<common, world> worldFromCommon;
uniform point<common> anchor;
uniform point<world> eye;

out vec3 toEye;

void main() {
    point<world> p = (worldFromCommon * vec4(anchor, 1.0)).xyz;
    toEye = eye - p;
    direction<common> up = normalize(vector<common>(anchor));
    mat3<world, common, rigid> frame = mat3(up, up, up);
    vec3 local = anchor in common;
    vec3 wrong = eye - anchor;
}
