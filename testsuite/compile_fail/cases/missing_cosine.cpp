// Forgetting the cosine in the rendering equation.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/spectrum.hpp>

using namespace safegi;

namespace cf {
spectrum<dim::radiance> estimate(spectrum<dim::radiance> Li, spectrum<dim::brdf> f, quantity<dim::proj> cos_theta,
                                 quantity<dim::pdf_solid_angle> pdf) {
  (void)cos_theta;
#ifndef FIXED
  return Li * f / pdf;
#else
  return Li * f * cos_theta / pdf;
#endif
}
}  // namespace cf

int main() { return 0; }
