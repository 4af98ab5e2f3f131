// Transforming a world ray with worldFromObject.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/ray.hpp>

using namespace safegi;

namespace cf {
ray<spaces::object> f(const map<spaces::object, spaces::world>& worldFromObject, const ray<spaces::world>& r) {
#ifndef FIXED
  return transform(worldFromObject, r);
#else
  return transform(inverse(worldFromObject), r);
#endif
}
}  // namespace cf

int main() { return 0; }
