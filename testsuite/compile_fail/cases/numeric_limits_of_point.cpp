// Asking std::numeric_limits for a point's infinity (the primary template answered the
// origin, so a bounding box "grown" from it started at 0 m).
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <limits>

#include <safegi/typed/space.hpp>

using namespace safegi;

namespace cf {
point<spaces::world> lower_corner_of_empty_box() {
#ifndef FIXED
  return std::numeric_limits<point<spaces::world>>::infinity();
#else
  const quantity<dim::length> inf = std::numeric_limits<quantity<dim::length>>::infinity();
  return point<spaces::world>(inf, inf, inf);
#endif
}
}  // namespace cf

int main() { return 0; }
