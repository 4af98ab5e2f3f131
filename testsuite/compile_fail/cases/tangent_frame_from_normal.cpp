// Building the frame a normal map is read in from the normal alone: from_normal picks
// an arbitrary azimuth, so the map's x (dp/du) would point anywhere around the normal.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/frame.hpp>

using namespace safegi;

namespace cf {
normal<spaces::world> mapped_normal(normal<spaces::world> n, vector<spaces::world> dpdu,
                                    normal<spaces::tangent> texel) {
#ifndef FIXED
  const frame<spaces::world, spaces::tangent> tbn = frame<spaces::world, spaces::tangent>::from_normal(n);
#else
  const frame<spaces::world, spaces::tangent> tbn = frame<spaces::world, spaces::tangent>::from_tangent(dpdu, n);
#endif
  return tbn.from_local(texel);
}
}  // namespace cf

int main() { return 0; }
