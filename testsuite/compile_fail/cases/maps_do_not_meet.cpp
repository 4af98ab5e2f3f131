// Composing maps whose spaces do not meet.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/map.hpp>

using namespace safegi;

namespace cf {
map<spaces::object, spaces::camera> f(const map<spaces::world, spaces::camera>& cameraFromWorld,
                                      const map<spaces::world, spaces::object>& objectFromWorld) {
#ifndef FIXED
  return cameraFromWorld * objectFromWorld;
#else
  return cameraFromWorld * inverse(objectFromWorld);
#endif
}
}  // namespace cf

int main() { return 0; }
