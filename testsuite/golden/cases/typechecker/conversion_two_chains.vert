#version 330 core
#include <safegi/prelude.sgl>
// Two routes of the same length from object to view: through world, or through the parent.
space object;
space parent;
space world;
space view;
uniform map<object, world> worldFromObject;
uniform map<object, parent> parentFromObject;
uniform rigidmap<world, view> viewFromWorld;
uniform map<parent, view> viewFromParent;
in point<object> position;
out point<view> viewPos;
void main() {
  viewPos = position in view;
  gl_Position = vec4(viewPos, 1.0);
}
