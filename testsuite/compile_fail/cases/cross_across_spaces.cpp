// Crossing vectors from different spaces.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/space.hpp>

using namespace safegi;

namespace cf {
vector<spaces::world, dim::area> f(vector<spaces::world> a, vector<spaces::object> b, vector<spaces::world> c) {
  (void)c;
#ifndef FIXED
  return cross(a, b);
#else
  return cross(a, c);
#endif
}
}  // namespace cf

int main() { return 0; }
