// Taking the local cosine of a world-space direction: abs_cos_theta reads z, which is
// the normal only in a frame's local space (world z is "up", whatever the surface).
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/frame.hpp>

using namespace safegi;

namespace cf {
quantity<dim::proj> cosine(const frame<spaces::world>& shading_frame, direction<spaces::world> wi_world) {
#ifndef FIXED
  return abs_cos_theta(wi_world);
#else
  return abs_cos_theta(shading_frame.to_local(wi_world));
#endif
}
}  // namespace cf

int main() { return 0; }
