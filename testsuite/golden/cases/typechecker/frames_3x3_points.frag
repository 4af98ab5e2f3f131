#version 330 core
#include <safegi/prelude.sgl>
// A 3×3 map has no translation: a point through it is refused; a mat3 annotation names
// two spaces and at most one of 'rigid' or 'normal'; a normal matrix is not the map itself.
space object;
space world;
uniform mat3<object, world> linear;
uniform mat3<object, world, normal> normals;
uniform mat3<object, world, rigids> misspelt;
in point<object> p;
out vec4 c;
void main() {
  point<world> q = linear * p;
  mat3<object, world> same = normals;
  c = vec4(q, 1.0);
}
