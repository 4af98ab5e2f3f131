#version 330 core
#include <safegi/prelude.sgl>
space object;
space view;
space clip;
uniform rigidmap<object, view> viewFromObject;
uniform projmap<view, clip> clipFromView;
in point<object> position;
void main() {
  projmap<object, clip> m = viewFromObject * clipFromView;
  gl_Position = m * position;
}
