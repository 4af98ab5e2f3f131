#version 330 core
#include <safegi/prelude.sgl>
// An input named like a type word (`normal`, as real vertex shaders name
// theirs) leaves the word a type where only a type can stand: a declaration
// `normal<world> n` or a cast `normal<world>(x)` after it.
space object;
space world;
uniform mat3<object, world, normal> normalMatrix;
in normal<object> normal;
out normal<world> worldNormal;
void main() {
    normal<world> n = normalize(normalMatrix * normal);
    worldNormal = normal<world>(n);
    gl_Position = vec4(normal, 1.0);
}
