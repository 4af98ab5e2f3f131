// A double literal times a unit is a double quantity; stored in a float build's
// quantity<D> it was a bare "no viable conversion" error that named no dimension.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/units.hpp>

using namespace safegi;

namespace cf {
quantity<dim::length> ray_offset() {
#ifndef FIXED
  quantity<dim::length> offset = 1e-4 * units::metre;
#else
  quantity<dim::length> offset = real(1e-4) * units::metre;
#endif
  return offset;
}
}  // namespace cf

int main() { return 0; }
