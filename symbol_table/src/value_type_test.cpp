#include "safegi/symbol_table/value_type.hpp"

#include <gtest/gtest.h>

namespace safegi::gl {
namespace {

const DimensionExponents kRadiance{{"energy", 1}, {"length", -2}, {"proj", -1}, {"solid_angle", -1}, {"time", -1}};

DimensionNamer rendering_namer() {
  DimensionNamer namer;
  namer.add("radiance", kRadiance);
  return namer;
}

TEST(ValueType, PrintsTypesInWords) {
  DimensionNamer namer = rendering_namer();
  EXPECT_EQ(in_words({Kind::spectrum, "vec3", {kRadiance, ""}, {}}, namer), "spectrum<radiance>");
  EXPECT_EQ(in_words({Kind::spectrum, "vec3", {{}, ""}, {}}, namer), "spectrum<1>");
  EXPECT_EQ(in_words({Kind::scalar, "float", {{{"length", 1}}, ""}, {}}, namer), "float<length>");
  EXPECT_EQ(in_words({Kind::scalar, "float", {{{"energy", 1}, {"length", -2}}, ""}, {}}, namer),
            "float<energy*length^-2>");
  EXPECT_EQ(in_words({Kind::point, "vec3", {}, {"world"}}, namer), "point<world>");
  EXPECT_EQ(in_words({Kind::map, "mat4", {}, {"object", "world"}}, namer), "map<object, world>");
  EXPECT_EQ(in_words({Kind::plain, "vec2", {}, {}}, namer), "vec2");
  ValueType texel{Kind::spectrum, "vec3", {kRadiance, ""}, {}};
  EXPECT_EQ(in_words({Kind::sampler, "sampler2D", {}, {}}, namer, &texel), "sampler2D<spectrum<radiance>>");
}

TEST(ValueType, AGivenNameWinsOverTheNamer) {
  EXPECT_EQ(in_words({Kind::spectrum, "vec3", {kRadiance, "L"}, {}}, rendering_namer()), "spectrum<L>");
}

TEST(ValueType, ListsWhatDiffers) {
  ValueType radiance{Kind::spectrum, "vec3", {kRadiance, ""}, {}};
  ValueType world_point{Kind::point, "vec3", {}, {"world"}};
  ValueType object_point{Kind::point, "vec3", {}, {"object"}};
  EXPECT_TRUE(differences(radiance, radiance).empty());
  EXPECT_EQ(differences(world_point, object_point), (std::vector<std::string>{"space"}));
  EXPECT_EQ(differences(radiance, world_point), (std::vector<std::string>{"kind", "dimension", "space"}));
  // A printed name is a label, not part of the type.
  EXPECT_TRUE(differences(radiance, {Kind::spectrum, "vec3", {kRadiance, "radiance"}, {}}).empty());
}

TEST(ValueType, KindNamesRoundTrip) {
  for (Kind kind : {Kind::plain, Kind::scalar, Kind::spectrum, Kind::point, Kind::vector, Kind::direction,
                    Kind::normal, Kind::hpoint, Kind::map, Kind::projective_map, Kind::sampler, Kind::block})
    EXPECT_EQ(kind_from_string(to_string(kind)), kind);
  EXPECT_FALSE(kind_from_string("colour").has_value());
}

}  // namespace
}  // namespace safegi::gl
