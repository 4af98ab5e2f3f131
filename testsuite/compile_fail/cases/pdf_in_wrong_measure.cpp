// Dividing by a pdf per area where a pdf per solid angle is needed.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/radiometry.hpp>
#include <safegi/typed/space.hpp>
#include <safegi/typed/spectrum.hpp>

using namespace safegi;

namespace cf {
spectrum<dim::radiance> estimate(spectrum<dim::radiance> Li, spectrum<dim::brdf> f, quantity<dim::proj> cos_theta,
                                 quantity<dim::pdf_area> pdf_area, quantity<dim::area> r2,
                                 normal<spaces::world> light_normal, direction<spaces::world> wi) {
  (void)r2; (void)light_normal; (void)wi;
#ifndef FIXED
  return Li * f * cos_theta / pdf_area;
#else
  const quantity<dim::pdf_solid_angle> pdf = pdf_area_to_solid_angle(pdf_area, r2, light_normal, wi);
  return Li * f * cos_theta / pdf;
#endif
}
}  // namespace cf

int main() { return 0; }
