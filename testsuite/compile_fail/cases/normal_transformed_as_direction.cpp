// Transforming a normal and using the result as a direction.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/map.hpp>

using namespace safegi;

namespace cf {
direction<spaces::world> f(const map<spaces::object, spaces::world>& worldFromObject, normal<spaces::object> n) {
#ifndef FIXED
  direction<spaces::world> d = worldFromObject(n);
  return d;
#else
  direction<spaces::world> d = to_direction(worldFromObject(n));  // transformed as a normal, then used
  return d;
#endif
}
}  // namespace cf

int main() { return 0; }
