// Storing a camera-space point in a world-space variable.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/space.hpp>

using namespace safegi;

namespace cf {
point<spaces::world> f(point<spaces::camera> p) {
#ifndef FIXED
  point<spaces::world> q = p;
  return q;
#else
  point<spaces::world> q(p.x(), p.y(), p.z());  // only right if camera == world here
  return q;
#endif
}
}  // namespace cf

int main() { return 0; }
