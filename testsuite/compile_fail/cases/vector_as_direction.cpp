// Using an unnormalised vector as a direction.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/space.hpp>

using namespace safegi;

namespace cf {
direction<spaces::world> f(point<spaces::world> a, point<spaces::world> b) {
#ifndef FIXED
  direction<spaces::world> w = b - a;
  return w;
#else
  direction<spaces::world> w = normalize(b - a);
  return w;
#endif
}
}  // namespace cf

int main() { return 0; }
