// Building a world point from an object point's coordinates: the braces claim world
// space for numbers that are object-space ones, and nothing at the call names a space.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/map.hpp>

using namespace safegi;

namespace cf {
quantity<dim::length> height(point<spaces::world> p) { return p.z(); }

quantity<dim::length> vertex_height(const map<spaces::object, spaces::world>& worldFromObject,
                                    point<spaces::object> vertex) {
#ifndef FIXED
  return height({vertex.x(), vertex.y(), vertex.z()});
#else
  return height(worldFromObject(vertex));
#endif
}
}  // namespace cf

int main() { return 0; }
