// Storing a pdf per area as a pdf per solid angle.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/quantity.hpp>

using namespace safegi;

namespace cf {
quantity<dim::pdf_solid_angle> light_pdf(quantity<dim::area> light_area) {
#ifndef FIXED
  quantity<dim::pdf_solid_angle> pdf = 1.0f / light_area;
  return pdf;
#else
  quantity<dim::pdf_area> pdf = 1.0f / light_area;
  return dimension_cast<dim::pdf_solid_angle>(pdf);  // greppable: this one is on purpose
#endif
}
}  // namespace cf

int main() { return 0; }
