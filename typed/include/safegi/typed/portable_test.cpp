// Code written against the portable API only. It is compiled twice — into
// safegi_typed_test (checked) and safegi_typed_unchecked_test (SAFEGI_UNCHECKED=1) —
// and must compile and give the same numbers in both.
#include <gtest/gtest.h>

#include <safegi/typed.hpp>
#include <safegi/typed/reflection.hpp>

namespace {
namespace sg = safegi;
using sg::dim::brdf;
using sg::dim::radiance;
SAFEGI_SPACE(world);
SAFEGI_SPACE(object);

struct light_sample {
  sg::spectrum<radiance> Li;
  sg::direction<world> wi;
  sg::quantity<sg::dim::length> distance;
  sg::quantity<sg::dim::pdf_solid_angle> pdf;
};

// A point light seen from p, written as a renderer would.
light_sample sample_point_light(sg::point<world> light, sg::spectrum<sg::dim::intensity> I, sg::point<world> p) {
  const sg::vector<world> to_light = light - p;
  const sg::quantity<sg::dim::area> r2 = sg::length_squared(to_light);
  // A point light is a delta in solid angle: its "pdf" is one per steradian.
  const sg::quantity<sg::dim::pdf_solid_angle> pdf = 1.0f / (1.0f * sg::units::steradian);
  // I / r² is irradiance at normal incidence; per unit projected solid angle it is radiance.
  const sg::spectrum<radiance> Li = I / r2 / sg::units::proj;
  return {Li, sg::normalize(to_light), sg::sqrt(r2), pdf};
}

sg::spectrum<radiance> shade(sg::point<world> p, sg::normal<world> n, sg::spectrum<brdf> f,
                             sg::point<world> light, sg::spectrum<sg::dim::intensity> I) {
  const light_sample s = sample_point_light(light, I, p);
  const sg::quantity<sg::dim::proj> cosine = sg::max(sg::dot(n, s.wi), sg::quantity<sg::dim::proj>(sg::zero));
  if (s.pdf <= sg::zero || s.distance <= sg::zero) return {};
  return s.Li * f * cosine / s.pdf;
}

TEST(Portable, ShadingGivesTheSameNumbersInBothModes) {
  const sg::point<world> p(0.0f * sg::units::metre, 0.0f * sg::units::metre, 0.0f * sg::units::metre);
  const sg::point<world> light(0.0f * sg::units::metre, 0.0f * sg::units::metre, 2.0f * sg::units::metre);
  const sg::spectrum<sg::dim::intensity> I(4.0f * sg::units::watt_per_steradian);
  const sg::spectrum<brdf> f = sg::dimension_cast<brdf>(sg::spectrum<sg::dim::dimensionless>(0.5f));
  const sg::spectrum<radiance> L = shade(p, sg::normal<world>(0, 0, 1), f, light, I);
  // I / r² · f · cos / pdf = 4 / 4 · 0.5 · 1 / 1
  EXPECT_FLOAT_EQ(sg::raw(L.r()), 0.5f);
  EXPECT_FLOAT_EQ(sg::raw(sg::luminance(L)), 0.5f);
}

TEST(Portable, TransformAndDot) {
  const auto worldFromObject = sg::map<object, world>::translation(sg::from_raw<sg::vector<world>>(glm::vec3(0, 0, 1))) *
                               sg::map<object, object>::scaling(1.0f, 1.0f, 2.0f);
  const sg::point<object> p = sg::from_raw<sg::point<object>>(glm::vec3(1, 2, 3));
  const sg::point<world> pw = worldFromObject(p);
  EXPECT_EQ(sg::raw(pw), glm::vec3(1, 2, 7));
  const sg::normal<world> n = worldFromObject(sg::normal<object>(0, 0.6f, 0.8f));
  const sg::direction<world> w = sg::normalize(sg::from_raw<sg::vector<world>>(glm::vec3(0, 0, 1)));
  const sg::quantity<sg::dim::proj> c = sg::dot(n, w);
  EXPECT_NEAR(sg::raw(c), 0.4f / std::sqrt(0.36f + 0.16f), 1e-6f);
  const sg::map<world, object> objectFromWorld = sg::inverse(worldFromObject);
  EXPECT_EQ(sg::raw(objectFromWorld(pw)), sg::raw(p));
  EXPECT_FLOAT_EQ(sg::in(sg::distance(pw, sg::point<world>{}), sg::units::millimetre), 1000.0f * std::sqrt(54.0f));
}

TEST(Portable, AnglesAndUnits) {
  const sg::quantity<sg::dim::angle> theta = 60.0f * sg::units::degree;
  EXPECT_NEAR(sg::cos(theta), 0.5f, 1e-6f);
  EXPECT_NEAR(sg::in(sg::acos(0.5f), sg::units::degree), 60.0f, 1e-4f);
  const sg::quantity<sg::dim::length> d = 25.4f * sg::units::millimetre;
  EXPECT_NEAR(sg::in(d, sg::units::inch), 1.0f, 1e-6f);
  sg::quantity<sg::dim::radiance> acc = sg::zero;
  acc += sg::dimension_cast<radiance>(2.0f);
  EXPECT_EQ(sg::raw(acc), 2.0f);
  const sg::frame<world> frame = sg::frame<world>::from_normal(sg::normal<world>(0, 0, 1));
  EXPECT_NEAR(sg::raw(sg::cos_theta(frame.to_local(sg::direction<world>(0.6f, 0, 0.8f)))), 0.8f, 1e-6f);
  EXPECT_EQ(sg::describe<sg::spectrum<radiance>>().kind, sg::type_kind::spectrum);
}
// std::numeric_limits of a quantity is the representation's in both modes (checked, it
// was the primary template's zero before: every ray reaching infinity() missed).
TEST(Portable, NumericLimitsOfQuantities) {
  using length = sg::quantity<sg::dim::length>;
  const length reach = std::numeric_limits<length>::infinity();
  EXPECT_EQ(sg::raw(reach), std::numeric_limits<sg::real>::infinity());
  EXPECT_TRUE(sg::isinf(reach));
  EXPECT_EQ(sg::raw(std::numeric_limits<length>::max()), std::numeric_limits<sg::real>::max());
  EXPECT_EQ(sg::raw(std::numeric_limits<length>::lowest()), std::numeric_limits<sg::real>::lowest());
  EXPECT_EQ(sg::raw(std::numeric_limits<length>::epsilon()), std::numeric_limits<sg::real>::epsilon());
  EXPECT_TRUE(sg::isnan(std::numeric_limits<sg::quantity<sg::dim::radiance>>::quiet_NaN()));
  EXPECT_LT(1.0f * sg::units::kilometre, reach);
}

// Unit vectors with each other and with vectors (the shader language's rules) compile
// and give the same numbers in both modes.
TEST(Portable, UnitVectorArithmetic) {
  const sg::normal<world> n(0.0f, 0.0f, 1.0f);
  const sg::normal<world> ng(0.0f, 1.0f, 0.0f);
  const sg::direction<world> w(1.0f, 0.0f, 0.0f);
  const sg::vector<world, sg::dim::dimensionless> bent = n - ng;
  EXPECT_EQ(sg::raw(bent + w), glm::vec3(1, -1, 1));
  EXPECT_EQ(sg::raw(sg::cross(n, w)), glm::vec3(0, 1, 0));
  const sg::vector<world> v(0.0f * sg::units::metre, 2.0f * sg::units::metre, 0.0f * sg::units::metre);
  EXPECT_EQ(sg::raw(sg::cross(v, w)), glm::vec3(0, 0, -2));
}

// Orientation (opt-in) builds in both modes: unchecked, oriented<O, X> is X.
float light_facing(sg::oriented<sg::away, sg::direction<world>> lens_to_light, sg::normal<world> n) {
  return -sg::raw(sg::dot(n, lens_to_light));
}

TEST(Portable, OrientedDirectionsToALight) {
  const sg::point<world> light(0.0f * sg::units::metre, 0.0f * sg::units::metre, 2.0f * sg::units::metre);
  const sg::shaded_point<world> lens = sg::shaded(sg::point<world>(sg::zero, sg::zero, sg::zero));
  const sg::oriented<sg::away, sg::direction<world>> wi = sg::normalize(light - lens);
  EXPECT_EQ(light_facing(wi, sg::normal<world>(0, 0, -1)), 1.0f);
  EXPECT_EQ(light_facing(-sg::normalize(lens - light), sg::normal<world>(0, 0, -1)), 1.0f);
  EXPECT_EQ(light_facing(sg::as_away(sg::direction<world>(0, 0, 1)), sg::normal<world>(0, 0, -1)), 1.0f);
}

// Geometric normals (opt-in) build in both modes: unchecked, geometric_normal<S> is normal<S>.
TEST(Portable, RayOffsetAlongTheGeometricNormal) {
  const sg::point<world> p0 = sg::from_raw<sg::point<world>>(glm::vec3(0, 0, 0));
  const sg::point<world> p1 = sg::from_raw<sg::point<world>>(glm::vec3(1, 0, 0));
  const sg::point<world> p2 = sg::from_raw<sg::point<world>>(glm::vec3(0, 1, 0));
  const sg::geometric_normal<world> ng = sg::face_normal(p0, p1, p2);
  const sg::point<world> o = sg::offset_ray_origin(p0, ng, 0.25f * sg::units::metre, sg::direction<world>(0, 0, -1));
  EXPECT_EQ(sg::raw(o), glm::vec3(0, 0, -0.25f));
  EXPECT_EQ(sg::raw(sg::offset_ray_origin(p0, sg::geometric(sg::normal<world>(0, 0, 1)), 0.25f * sg::units::metre,
                                          sg::direction<world>(0, 0, 1))),
            glm::vec3(0, 0, 0.25f));
}

}  // namespace
