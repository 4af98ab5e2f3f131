// Applying worldFromObject to a camera-space point.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/map.hpp>

using namespace safegi;

namespace cf {
point<spaces::world> f(const map<spaces::object, spaces::world>& worldFromObject, point<spaces::camera> p,
                       point<spaces::object> p_object) {
  (void)p_object;
#ifndef FIXED
  return worldFromObject(p);
#else
  return worldFromObject(p_object);
#endif
}
}  // namespace cf

int main() { return 0; }
