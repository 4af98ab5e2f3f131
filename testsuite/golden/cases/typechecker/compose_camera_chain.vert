#version 330 core
#include <safegi/prelude.sgl>
// The model-view-projection chain: projective after rigid after affine is projective.
space object;
space world;
space view;
space clip;
uniform map<object, world> worldFromObject;
uniform rigidmap<world, view> viewFromWorld;
uniform projmap<view, clip> clipFromView;
uniform projmap<clip, clip> jitter;          // a sub-pixel offset after the projection
in point<object> position;
out point<view> viewPos;
void main() {
  projmap<object, clip> clipFromObject = jitter * clipFromView * viewFromWorld * worldFromObject;
  map<object, view> viewFromObject = viewFromWorld * worldFromObject;
  map<world, view> widened = viewFromWorld;  // a rigid map is a map
  viewPos = viewFromObject * position;
  gl_Position = clipFromObject * position;
}
