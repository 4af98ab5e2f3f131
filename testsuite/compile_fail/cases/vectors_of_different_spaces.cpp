// Adding vectors from different spaces.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/space.hpp>

using namespace safegi;

namespace cf {
vector<spaces::world> f(vector<spaces::world> a, vector<spaces::camera> b) {
#ifndef FIXED
  return a + b;
#else
  return a + vector<spaces::world>(b.x(), b.y(), b.z());  // only right if camera == world here
#endif
}
}  // namespace cf

int main() { return 0; }
