#version 330 core
#include <safegi/prelude.sgl>
space object;
space world;
space view;
uniform map<object, world> worldFromObject;
uniform rigidmap<view, world> worldFromView;   // the camera's pose, not the view matrix
in point<object> position;
out point<view> viewPos;
void main() {
  viewPos = position in view;
  gl_Position = vec4(viewPos, 1.0);
}
