// Offsetting a secondary ray's origin along the bumped shading normal: on a grazing
// direction its side can differ from the surface's, and the ray starts under the surface.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/geometric_normal.hpp>
#include <safegi/typed/units.hpp>

using namespace safegi;

namespace cf {
point<spaces::world> next_origin(point<spaces::world> p, point<spaces::world> p1, point<spaces::world> p2,
                                 normal<spaces::world> n_shading, direction<spaces::world> wi) {
  const quantity<dim::length> epsilon = real(1e-4) * units::metre;
#ifndef FIXED
  (void)p1, (void)p2;
  return offset_ray_origin(p, n_shading, epsilon, wi);
#else
  (void)n_shading;
  return offset_ray_origin(p, face_normal(p, p1, p2), epsilon, wi);
#endif
}
}  // namespace cf

int main() { return 0; }
