// The unchecked build: the same headers with SAFEGI_UNCHECKED=1. Every typed name is
// its plain representation; the kinds whose transforms differ stay distinct types.
#include <gtest/gtest.h>

#include <safegi/typed.hpp>
#include <safegi/typed/reflection.hpp>
#include <typeinfo>

#if !SAFEGI_UNCHECKED
#error "unchecked_test.cpp must be built with SAFEGI_UNCHECKED=1 (link SafeGI::typed_unchecked)"
#endif

namespace {
using namespace safegi;
SAFEGI_SPACE(world);
SAFEGI_SPACE(object);

static_assert(!is_checked);
static_assert(std::is_same_v<quantity<dim::radiance>, float>);
static_assert(std::is_same_v<quantity<dim::length, double>, double>);
static_assert(std::is_same_v<spectrum<dim::radiance>, spectrum<dim::irradiance>>);
static_assert(std::is_same_v<point<world>, point<object>>);
static_assert(std::is_same_v<map<object, world>, map<world, object>>);
static_assert(std::is_same_v<vector<world>, vector<object, dim::area>>);
// Kinds that transform differently stay apart.
static_assert(!std::is_same_v<point<world>, vector<world>>);
static_assert(!std::is_same_v<vector<world>, normal<world>>);
static_assert(!std::is_same_v<direction<world>, normal<world>>);
static_assert(std::is_same_v<decltype(dot(normal<world>{}, direction<world>{})), float>);

TEST(Unchecked, NamesLiveInTheirOwnNamespace) {
  // Object files of the two modes cannot be linked into one silently: the mangled
  // names differ (safegi::unchecked:: vs safegi::checked::).
  const std::string name = typeid(point<world>).name();
  EXPECT_NE(name.find("9unchecked"), std::string::npos) << name;
}

TEST(Unchecked, MistakesCompile) {
  // What the checked build rejects is accepted here: nothing is checked.
  const quantity<dim::radiance> L = 1.0f;
  const quantity<dim::irradiance> E = 2.0f;
  EXPECT_EQ(L + E, 3.0f);
  EXPECT_FLOAT_EQ(safegi::sin(0.5f), std::sin(0.5f));
  EXPECT_FLOAT_EQ(safegi::sqrt(4.0f), 2.0f);
}

TEST(Unchecked, DescriptionsCarryKindOnly) {
  const type_description d = describe<spectrum<dim::radiance>>();
  EXPECT_FALSE(d.checked);
  EXPECT_EQ(d.kind, type_kind::spectrum);
  EXPECT_TRUE(d.dimension.empty());
  EXPECT_TRUE(d.dimension_name.empty());
  EXPECT_EQ(describe<point<world>>().kind, type_kind::point);
  EXPECT_TRUE(describe<point<world>>().space.empty());
  EXPECT_EQ(describe<quantity<dim::radiance>>().kind, type_kind::scalar);
  EXPECT_EQ((describe<map<object, world>>().to_string()), "map");
}
}  // namespace

namespace {
// Printing: nothing but the numbers and the kind survive the unchecked build.
TEST(Unchecked, PrintingShowsNumbersAndKinds) {
  using namespace safegi;
  EXPECT_EQ(safegi::to_string(point<world>(1.0f * units::metre, 2.0f * units::metre, 0.0f * units::metre)),
            "point(1, 2, 0)");
  EXPECT_EQ(safegi::to_string(direction<world>(0, 0, 1)), "direction(0, 0, 1)");
  EXPECT_EQ(safegi::to_string(spectrum<dim::radiance>(2.0f * units::radiance_unit)), "(2, 2, 2)");
}
}  // namespace
