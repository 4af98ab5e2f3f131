#version 330 core
#include <safegi/prelude.sgl>
// 3×3 maps: mat3<A, B> a linear map, mat3<A, B, rigid> a rotation (a frame), mat3<A, B, normal>
// the normal matrix; mat3(m) of a map is its linear part and mat3(T, B, N) of unit vectors a frame.
// A normal through a linear map that may scale, a vector through a normal matrix, a value of
// another space and a point through a 3×3 map are told.
space tangent;
space object;
space world;
space view;
uniform map<object, world> model;
uniform rigidmap<world, view> viewM;
uniform mat3<object, view, normal> normalMatrix;
uniform mat3<tangent, world, rigid> tbnUniform;
uniform samplerCube irradianceMap;
uniform sampler2D normalMap;
in normal<world> N;
in direction<world> T;
in direction<world> B;
in normal<object> nObj;
in vector<object, 1> tObj;
in vec2 uv;
out vec4 c;
void main() {
  mat3 TBN = mat3(T, B, N);
  normal<world> n = normalize(TBN * (texture(normalMap, uv).xyz * 2.0 - 1.0));
  mat3<tangent, world, rigid> TBN2 = mat3<tangent, world, rigid>(T, B, N);
  direction<tangent> wT = transpose(TBN2) * normalize(N + T);
  normal<view> nV = normalize(normalMatrix * nObj);
  normal<world> nW = normalize(transpose(inverse(mat3(model))) * nObj);
  normal<world> nW2 = normalize(mat3(model) * nObj);
  vector<view, 1> tV = normalMatrix * tObj;
  vector<world, 1> tW = mat3(model) * tObj;
  normal<view> nV2 = mat3(viewM) * n;
  normal<view> nV3 = mat3(viewM) * nObj;
  c = vec4(n + wT, 1.0);
}
