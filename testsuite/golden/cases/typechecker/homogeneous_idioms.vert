#version 330 core
#include <safegi/prelude.sgl>
// w = 1 is a point and w = 0 a vector, direction or normal under a map: the idioms of
// real vertex shaders check, and a normal taken through the model matrix, a point given
// w = 0 or a normal given w = 1 is told as such.
space object;
space world;
space view;
space clip;
uniform map<object, world> model;
uniform rigidmap<world, view> viewM;
uniform projmap<view, clip> proj;
in point<object> aPos;
in normal<object> aNormal;
in vector<object, 1> aTangent;
out point<world> vWorld;
out normal<world> vNormal;
out normal<world> vNormalBad;
out normal<world> vNormal2;
out vector<world, 1> vTangent;
void main() {
  vec4 worldPos = model * vec4(aPos, 1.0);
  vWorld = worldPos.xyz;
  vNormal = normalize((vec4(aNormal, 0.0) * inverse(model)).xyz);
  vNormal2 = normalize((transpose(inverse(model)) * vec4(aNormal, 0.0)).xyz);
  vTangent = (model * vec4(aTangent, 0.0)).xyz;
  gl_Position = proj * viewM * model * vec4(aPos, 1.0);
  gl_Position = proj * (viewM * worldPos);
  vNormalBad = normalize((model * vec4(aNormal, 0.0)).xyz);
  vWorld = vec3(model * vec4(aPos, 0.0));
  vNormalBad = normalize(vec3(model * vec4(aNormal, 1.0)));
  vWorld = (viewM * worldPos).xyz;
}
