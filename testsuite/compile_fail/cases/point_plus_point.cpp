// Adding two points.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/space.hpp>

using namespace safegi;

namespace cf {
point<spaces::world> midpoint(point<spaces::world> a, point<spaces::world> b) {
#ifndef FIXED
  return (a + b);
#else
  return lerp(a, b, 0.5f);
#endif
}
}  // namespace cf

int main() { return 0; }
