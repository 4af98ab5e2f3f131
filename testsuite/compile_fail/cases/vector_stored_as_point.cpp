// Storing a vector in a point variable.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/space.hpp>

using namespace safegi;

namespace cf {
point<spaces::world> f(point<spaces::world> a, point<spaces::world> b) {
#ifndef FIXED
  point<spaces::world> q = b - a;
  return q;
#else
  point<spaces::world> q = a + (b - a);
  return q;
#endif
}
}  // namespace cf

int main() { return 0; }
