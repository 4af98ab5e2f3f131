// pbrt-v3's mix material as the importer reads it (src/materials/mixmat.cpp
// and MakeMaterial in src/core/api.cpp): "amount" (a spectrum, default 0.5)
// weighs "namedmaterial1", 1 − amount "namedmaterial2"; an undefined name is
// pbrt-v3's default matte with a message; the parts keep their own values.
#include <gtest/gtest.h>

#include "pbrt/pbrt_import_test_support.hpp"

namespace safegi::render {
namespace {

using namespace pbrt_test;

TEST(PbrtImport, MixOfNamedMaterials) {
  PbrtScene scene = import(world(
      "MakeNamedMaterial \"gold\" \"string type\" \"metal\"\n"
      "MakeNamedMaterial \"paint\" \"string type\" \"matte\" \"rgb Kd\" [0.1 0.2 0.3]\n"
      "Material \"mix\" \"string namedmaterial1\" \"gold\" \"string namedmaterial2\" \"paint\" "
      "\"rgb amount\" [0.2 0.2 0.5]\nShape \"sphere\"\n"                                             // 0
      "MakeNamedMaterial \"half\" \"string type\" \"mix\" \"string namedmaterial1\" \"paint\" "
      "\"string namedmaterial2\" \"gold\"\nNamedMaterial \"half\"\nShape \"sphere\"\n"              // 1: amount 0.5
      "Material \"mix\" \"string namedmaterial1\" \"half\" \"string namedmaterial2\" \"paint\" "
      "\"rgb amount\" [0.25 0.25 0.25]\nShape \"sphere\"\n"));                                                // 2: nested
  const Scene& s = scene.scene;
  ASSERT_EQ(s.shapes.size(), 3u);
  auto mix_of = [&](size_t shape) {
    const Material& material = s.materials.at(s.shapes[shape].material);
    EXPECT_TRUE(material.mix) << shape;
    return material.mix.value_or(MaterialMix{});
  };
  const MaterialMix first = mix_of(0);
  EXPECT_TRUE(is<ConductorMaterial>(s.materials.at(first.first)));  // amount weighs namedmaterial1
  EXPECT_EQ(sg::raw(diffuse(s.materials.at(first.second)).value), glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(sg::raw(first.amount.value), glm::vec3(0.2f, 0.2f, 0.5f));
  const MaterialMix half = mix_of(1);
  EXPECT_EQ(sg::raw(half.amount.value), glm::vec3(0.5f));
  EXPECT_EQ(half.first, first.second);  // a named material is made once
  EXPECT_EQ(half.second, first.first);
  const MaterialMix nested = mix_of(2);
  EXPECT_EQ(nested.first, s.shapes[1].material);
  EXPECT_EQ(sg::raw(nested.amount.value), glm::vec3(0.25f));
  EXPECT_EQ(scene.warnings, "");
}

TEST(PbrtImport, MixWarningsAndRefusals) {
  PbrtScene undefined = import(world(
      "MakeNamedMaterial \"paint\" \"string type\" \"matte\"\n"
      "Material \"mix\" \"string namedmaterial1\" \"paint\" \"string namedmaterial2\" \"pain\"\nShape \"sphere\""));
  EXPECT_EQ(first_line(undefined.warnings),
            "scene.pbrt:3:72: warning: \"namedmaterial2\" of Material \"mix\" names no material (\"pain\"): rendered "
            "as matte");
  const Material& mix = undefined.scene.materials.at(undefined.scene.shapes[0].material);
  ASSERT_TRUE(mix.mix);
  EXPECT_EQ(sg::raw(as<LambertMaterial>(undefined.scene.materials.at(mix.mix->second)).diffuse.value), glm::vec3(0.5f));
  EXPECT_EQ(first_line(import_error(world(
                "MakeNamedMaterial \"air\" \"string type\" \"none\"\nMakeNamedMaterial \"paint\" \"string type\" \"matte\"\n"
                "Material \"mix\" \"string namedmaterial1\" \"air\" \"string namedmaterial2\" \"paint\"\nShape \"sphere\""))),
            "scene.pbrt:4:16: error: \"namedmaterial1\" of Material \"mix\" names a material \"none\", which is no surface");
  EXPECT_EQ(first_line(import_error(world(
                "MakeNamedMaterial \"paint\" \"string type\" \"matte\"\n"
                "Material \"mix\" \"string namedmaterial1\" \"paint\" \"string namedmaterial2\" \"paint\" "
                "\"rgb amount\" [0.5 1.5 0.5]\nShape \"sphere\""))),
            "scene.pbrt:3:80: error: \"amount\" of Material \"mix\" must lie in [0, 1] in every channel");
}

}  // namespace
}  // namespace safegi::render
