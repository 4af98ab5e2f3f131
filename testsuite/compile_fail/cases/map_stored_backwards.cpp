// Storing an inverse map under the forward name.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/map.hpp>

using namespace safegi;

namespace cf {
map<spaces::object, spaces::world> f(const map<spaces::object, spaces::world>& worldFromObject) {
#ifndef FIXED
  map<spaces::object, spaces::world> objectFromWorld = inverse(worldFromObject);
  return objectFromWorld;
#else
  map<spaces::world, spaces::object> objectFromWorld = inverse(worldFromObject);
  return inverse(objectFromWorld);
#endif
}
}  // namespace cf

int main() { return 0; }
