// Reading an absolute azimuth (anisotropic roughness along the tangent) in a frame built
// from the normal alone, whose tangent points anywhere around the normal.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/frame.hpp>

using namespace safegi;

namespace cf {
real alpha(direction<spaces::shading> wh, direction<spaces::tangent> wh_tangent, real alpha_u, real alpha_v) {
  (void)wh_tangent;
#ifndef FIXED
  const real c = cos_phi(wh);
  const real s = sin_phi(wh);
#else
  const real c = cos_phi(wh_tangent);
  const real s = sin_phi(wh_tangent);
  (void)wh;
#endif
  return c * c * alpha_u + s * s * alpha_v;
}
}  // namespace cf

int main() { return 0; }
