#version 330 core
#include <safegi/prelude.sgl>
// 'in' becomes the product of the maps on the chain, applied like transform().
space object;
space world;
space view;
space clip;
uniform map<object, world> worldFromObject;
uniform rigidmap<world, view> viewFromWorld;
uniform projmap<view, clip> clipFromView;
in point<object> position;
in normal<object> normalIn;
in vector<object> tangentIn;
in direction<world> toSun;
out point<view> viewPos;
out normal<view> viewNormal;
out vector<view> viewTangent;
out direction<view> sunInView;
void main() {
  viewPos = position in view;
  viewNormal = normalIn in view;
  viewTangent = tangentIn in view;
  sunInView = toSun in view;          // through a rigid map a direction stays one
  gl_Position = position in clip;
}
