#version 330 core
#include <safegi/prelude.sgl>
// Conversions bind tighter than '*' and looser than unary operators.
space object;
space world;
uniform map<object, world> worldFromObject;
uniform point<world> lightPos;
in point<object> position;
in vector<object> offset;
out vector<world> toLight;
out vector<world> pushed;
void main() {
  toLight = lightPos - position in world;
  pushed = 2.0 * offset in world + -offset in world;
  point<world> again = (position in world) in world;
  gl_Position = vec4(again, 1.0);
}
