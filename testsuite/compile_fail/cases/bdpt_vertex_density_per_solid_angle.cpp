// A bidirectional path tracer keeps each vertex's density per unit area, but a
// BSDF samples its direction per solid angle: storing the one as the other
// drops the Jacobian |cos θ| / r² of the vertex the direction reaches.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/radiometry.hpp>
#include <safegi/typed/space.hpp>

using namespace safegi;

namespace cf {
quantity<dim::pdf_area> vertex_density(quantity<dim::pdf_solid_angle> bsdf_pdf, quantity<dim::area> r2,
                                       normal<spaces::world> next_normal, direction<spaces::world> w) {
  (void)r2; (void)next_normal; (void)w;
#ifndef FIXED
  const quantity<dim::pdf_area> fwd = bsdf_pdf;
#else
  const quantity<dim::pdf_area> fwd = pdf_solid_angle_to_area(bsdf_pdf, r2, next_normal, w);
#endif
  return fwd;
}
}  // namespace cf

int main() { return 0; }
