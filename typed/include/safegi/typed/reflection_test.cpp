#include "safegi/typed/reflection.hpp"

#include <gtest/gtest.h>

namespace {
using namespace safegi;
SAFEGI_SPACE(world);
SAFEGI_SPACE(object);
SAFEGI_BASE_DIMENSION(pixel);

TEST(Reflection, ScalarsCarryTheirDimension) {
  const type_description d = describe<quantity<dim::irradiance>>();
  EXPECT_EQ(d.kind, type_kind::scalar);
  EXPECT_EQ(d.scalar, scalar_type::float32);
  EXPECT_TRUE(d.checked);
  EXPECT_EQ(d.dimension_name, "irradiance");
  const std::vector<dimension_term> expected{{"energy", 1}, {"length", -2}, {"time", -1}};
  EXPECT_EQ(d.dimension, expected);
  EXPECT_EQ(d.to_string(), "float<irradiance>");
  EXPECT_EQ((describe<quantity<dim::length, double>>().scalar), scalar_type::float64);
  EXPECT_EQ(describe<float>().to_string(), "float");
  EXPECT_TRUE(describe<float>().dimension.empty());
}

TEST(Reflection, SpectraAndUserDimensions) {
  EXPECT_EQ(describe<spectrum<dim::radiance>>().to_string(), "spectrum<radiance>");
  EXPECT_EQ(describe<spectrum<dim::radiance>>().dimension.size(), 5u);
  const auto d = describe<quantity<dim::product<pixel, pixel>>>();
  EXPECT_EQ(d.dimension, (std::vector<dimension_term>{{"pixel", 2}}));
  EXPECT_EQ(d.to_string(), "float<pixel^2>");
}

TEST(Reflection, SpacesByName) {
  EXPECT_EQ(describe<point<world>>().kind, type_kind::point);
  EXPECT_EQ(describe<point<world>>().space, "world");
  EXPECT_EQ(describe<point<world>>().to_string(), "point<world>");
  EXPECT_EQ(describe<vector<world>>().to_string(), "vector<world>");
  EXPECT_EQ(describe<vector<world>>().dimension_name, "length");
  EXPECT_EQ((describe<vector<world, dim::radiance>>().to_string()), "vector<world, radiance>");
  EXPECT_EQ(describe<direction<object>>().to_string(), "direction<object>");
  EXPECT_EQ(describe<normal<world>>().to_string(), "normal<world>");
  EXPECT_EQ(describe<hpoint<world>>().to_string(), "hpoint<world>");
  EXPECT_EQ(describe<ray<world>>().to_string(), "ray<world>");
  const auto m = describe<map<object, world>>();
  EXPECT_EQ(m.kind, type_kind::map);
  EXPECT_EQ(m.space, "object");
  EXPECT_EQ(m.target_space, "world");
  EXPECT_EQ(m.to_string(), "map<object, world>");
  EXPECT_EQ((describe<projective_map<world, spaces::clip>>().to_string()), "projective_map<world, clip>");
  EXPECT_EQ(describe<frame<world>>().to_string(), "frame<world, shading>");
}

TEST(Reflection, DescriptionsCompare) {
  EXPECT_EQ(describe<spectrum<dim::brdf>>(), describe<spectrum<dim::pdf_projected_solid_angle>>());
  EXPECT_NE(describe<spectrum<dim::radiance>>(), describe<spectrum<dim::irradiance>>());
  EXPECT_NE(describe<point<world>>(), describe<point<object>>());
}
}  // namespace
