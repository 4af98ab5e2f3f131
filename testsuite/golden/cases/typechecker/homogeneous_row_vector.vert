#version 330 core
#include <safegi/prelude.sgl>
// v * m multiplies by the transpose of m: the inverse transpose of a map carries normals
// backwards, anything else through it is the transpose where the map was meant.
space object;
space world;
uniform map<object, world> model;
uniform rigidmap<object, world> rigidModel;
in point<object> aPos;
in normal<object> aNormal;
in vector<object, 1> aTangent;
out normal<world> vNormal;
out vector<world, 1> vTangent;
void main() {
  vNormal = (vec4(aNormal, 0.0) * inverse(rigidModel)).xyz;
  vTangent = (vec4(aTangent, 0.0) * inverse(rigidModel)).xyz;
  vTangent = (vec4(aTangent, 0.0) * inverse(model)).xyz;
  vNormal = (transpose(inverse(model)) * (transpose(inverse(model)) * vec4(aNormal, 0.0))).xyz;
  gl_Position = vec4(aPos, 1.0) * model;
}
