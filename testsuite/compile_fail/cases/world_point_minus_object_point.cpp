// Subtracting an object-space point from a world-space point.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/space.hpp>

using namespace safegi;

namespace cf {
vector<spaces::world> f(point<spaces::world> p, point<spaces::object> q) {
#ifndef FIXED
  return p - q;
#else
  return p - point<spaces::world>(q.x(), q.y(), q.z());  // only right if object == world here
#endif
}
}  // namespace cf

int main() { return 0; }
