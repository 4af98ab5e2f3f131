// Adding pdfs of different measures (multiple importance sampling).
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/quantity.hpp>

using namespace safegi;

namespace cf {
quantity<dim::pdf_solid_angle> mis(quantity<dim::pdf_solid_angle> bsdf_pdf, quantity<dim::pdf_area> light_pdf,
                                    quantity<dim::pdf_solid_angle> light_pdf_omega) {
  (void)light_pdf_omega;
#ifndef FIXED
  return bsdf_pdf + light_pdf;
#else
  return bsdf_pdf + light_pdf_omega;
#endif
}
}  // namespace cf

int main() { return 0; }
