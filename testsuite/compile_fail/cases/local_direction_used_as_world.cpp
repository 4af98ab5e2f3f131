// Using a local (shading-space) direction in world space.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/frame.hpp>

using namespace safegi;

namespace cf {
quantity<dim::proj> f(const frame<spaces::world>& shading_frame, direction<spaces::shading> wi_local) {
#ifndef FIXED
  return dot(shading_frame.normal(), wi_local);
#else
  return dot(shading_frame.normal(), shading_frame.from_local(wi_local));
#endif
}
}  // namespace cf

int main() { return 0; }
