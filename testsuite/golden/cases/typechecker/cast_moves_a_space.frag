#version 330 core
#include <safegi/prelude.sgl>
// A cast adopts an unannotated value, never one of another space.
space object;
space world;
uniform point<object> lightObject;
uniform map<object, world> worldFromObject;
uniform map<object, world> previousWorldFromObject;
in vec3 raw;
out vec4 c;
void main() {
  point<world> adopted = point<world>(raw);
  point<world> moved = point<world>(lightObject);
  map<world, object> backwards = map<world, object>(worldFromObject);
  c = vec4(adopted - moved, 1.0);
}
