// Joining a light subpath's vertex (throughput: power) to a camera subpath's:
// the two f·|cos θ| are densities per solid angle, and without the geometry
// term's inverse-square law (per projected area) the product is no radiance.
// Compiled as is it must fail; compiled with -DFIXED it must build cleanly.
#include <safegi/typed/radiometry.hpp>
#include <safegi/typed/space.hpp>
#include <safegi/typed/spectrum.hpp>

using namespace safegi;

namespace cf {
spectrum<dim::radiance> connect(spectrum<dim::power> light_beta, spectrum<dim::dimensionless> camera_beta,
                                spectrum<dim::pdf_solid_angle> f_light, spectrum<dim::pdf_solid_angle> f_camera,
                                quantity<dim::length> distance) {
  (void)distance;
#ifndef FIXED
  return light_beta * f_light * f_camera * camera_beta;
#else
  return light_beta * f_light * f_camera * camera_beta * solid_angle_per_projected_area(distance);
#endif
}
}  // namespace cf

int main() { return 0; }
