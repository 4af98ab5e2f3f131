// A frame whose local space is a plain space: nothing says whether its azimuth follows
// dp/du or is arbitrary, so cos_theta and from_normal could not tell.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/frame.hpp>

using namespace safegi;

namespace cf {
#ifndef FIXED
SAFEGI_SPACE(lobe);
#else
SAFEGI_NORMAL_FRAME_SPACE(lobe);
#endif
direction<spaces::world> around(direction<spaces::world> axis, direction<lobe> local) {
  const frame<spaces::world, lobe> f = frame<spaces::world, lobe>::from_normal(to_normal(axis));
  return f.from_local(local);
}
}  // namespace cf

int main() { return 0; }
