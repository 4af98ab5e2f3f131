// Dotting a world normal with an object direction.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/space.hpp>

using namespace safegi;

namespace cf {
quantity<dim::proj> f(normal<spaces::world> n, direction<spaces::object> w, direction<spaces::world> w_world) {
  (void)w_world;
#ifndef FIXED
  return dot(n, w);
#else
  return dot(n, w_world);
#endif
}
}  // namespace cf

int main() { return 0; }
