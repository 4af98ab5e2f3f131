// Taking an object-space direction into a world shading frame.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/frame.hpp>

using namespace safegi;

namespace cf {
direction<spaces::shading> f(const frame<spaces::world>& shading_frame, direction<spaces::object> w,
                             direction<spaces::world> w_world) {
  (void)w_world;
#ifndef FIXED
  return shading_frame.to_local(w);
#else
  return shading_frame.to_local(w_world);
#endif
}
}  // namespace cf

int main() { return 0; }
