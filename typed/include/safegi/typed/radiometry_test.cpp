#include "safegi/typed/radiometry.hpp"

#include <gtest/gtest.h>

namespace {
using namespace safegi;

TEST(Radiometry, ChangesOfMeasureAreInverse) {
  const quantity<dim::pdf_area> pA = 1.0f / (2.0f * units::square_metre);
  const quantity<dim::area> r2 = 9.0f * units::square_metre;
  const quantity<dim::proj> cos_light = dimension_cast<dim::proj>(-0.5f);
  const quantity<dim::pdf_solid_angle> pw = pdf_area_to_solid_angle(pA, r2, cos_light);
  EXPECT_FLOAT_EQ(raw(pw), 0.5f * 9.0f / 0.5f);
  EXPECT_FLOAT_EQ(raw(pdf_solid_angle_to_area(pw, r2, cos_light)), raw(pA));
}
}  // namespace
