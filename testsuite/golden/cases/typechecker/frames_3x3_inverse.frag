#version 330 core
#include <safegi/prelude.sgl>
// inverse of a 3×3 map swaps its spaces, and transpose(inverse(mat3(m))) is m's normal matrix:
// it carries normals, not tangents, and its spaces are checked.
space object;
space world;
uniform map<object, world> model;
in normal<object> nObj;
in vector<object, 1> tObj;
out vec4 c;
void main() {
  normal<world> n = normalize(transpose(inverse(mat3(model))) * nObj);
  mat3<object, world> backwards = inverse(mat3(model));
  vector<world, 1> t = transpose(inverse(mat3(model))) * tObj;
  c = vec4(n + t, 1.0);
}
