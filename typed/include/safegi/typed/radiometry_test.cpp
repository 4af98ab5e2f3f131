#include "safegi/typed/radiometry.hpp"

#include <gtest/gtest.h>

namespace {
using namespace safegi;
using spaces::world;

TEST(Radiometry, ChangesOfMeasureAreInverse) {
  const quantity<dim::pdf_area> pA = 1.0f / (2.0f * units::square_metre);
  const quantity<dim::area> r2 = 9.0f * units::square_metre;
  // The light faces away from w at 60 degrees: |cos θ_l| = 0.5 whichever way w points.
  const normal<world> light_normal(0.0f, 0.0f, 1.0f);
  const direction<world> w(0.0f, std::sqrt(0.75f), -0.5f);
  const quantity<dim::pdf_solid_angle> pw = pdf_area_to_solid_angle(pA, r2, light_normal, w);
  EXPECT_FLOAT_EQ(raw(pw), 0.5f * 9.0f / 0.5f);
  EXPECT_FLOAT_EQ(raw(pdf_area_to_solid_angle(pA, r2, light_normal, -w)), raw(pw));
  EXPECT_FLOAT_EQ(raw(pdf_solid_angle_to_area(pw, r2, light_normal, w)), raw(pA));
}

TEST(Radiometry, InverseSquareLawGivesAPointLightsIrradiance) {
  // I = 4 W/sr at 2 m, receiver tilted by 60 degrees: E = I cos θ / r² = 4 · 0.5 / 4 W/m².
  const quantity<dim::intensity> I = 4.0f * units::watt_per_steradian;
  const normal<world> n(0.0f, 0.0f, 1.0f);
  const direction<world> wi(std::sqrt(0.75f), 0.0f, 0.5f);
  const quantity<dim::irradiance> E = I * solid_angle_per_projected_area(2.0f * units::metre) * dot(n, wi);
  EXPECT_FLOAT_EQ(in(E, units::watt_per_square_metre), 0.5f);
  // Per projected area: without the receiver's cosine the result is not an irradiance.
  static_assert(!std::is_same_v<dimension_of<decltype(I * solid_angle_per_projected_area(1.0f * units::metre))>,
                                dim::irradiance>);
}
}  // namespace
