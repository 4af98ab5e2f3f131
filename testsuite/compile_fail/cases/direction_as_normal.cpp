// Using a direction where a normal is expected.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/space.hpp>

using namespace safegi;

namespace cf {
quantity<dim::proj> f(direction<spaces::world> geometric_up, direction<spaces::world> w) {
#ifndef FIXED
  normal<spaces::world> n = geometric_up;
  return dot(n, w);
#else
  normal<spaces::world> n = to_normal(geometric_up);
  return dot(n, w);
#endif
}
}  // namespace cf

int main() { return 0; }
