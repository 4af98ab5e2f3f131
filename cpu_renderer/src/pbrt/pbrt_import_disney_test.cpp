// pbrt-v3's disney material as the importer reads it: the parameters and
// defaults of its CreateDisneyMaterial (src/materials/disney.cpp), a shape's
// own values, thin surfaces, the winding of its interface, and what is
// refused (an anisotropic lobe, subsurface scattering, textured weights)
// with the parameter's place.
#include <gtest/gtest.h>

#include "pbrt/pbrt_import_test_support.hpp"

namespace safegi::render {
namespace {

using namespace pbrt_test;

// "color" 0.5 (constant or texture), "metallic" 0, "eta" 1.5, "roughness"
// 0.5, "speculartint" 0, "anisotropic" 0, "sheen" 0, "sheentint" 0.5,
// "clearcoat" 0, "clearcoatgloss" 1, "spectrans" 0.
TEST(PbrtImport, DisneyAsPbrtV3DefinesIt) {
  PbrtScene scene = import(world(
      "Material \"disney\"\nShape \"sphere\"\n"  // 0: pbrt-v3's defaults
      "Material \"disney\" \"rgb color\" [0.2 0.3 0.4] \"float metallic\" 0.25 \"float eta\" 1.33 "
      "\"float roughness\" 0.7 \"float speculartint\" 0.1 \"float anisotropic\" 0 \"float sheen\" 0.6 "
      "\"float sheentint\" 0.2 \"float clearcoat\" 0.9 \"float clearcoatgloss\" 0.35 \"float spectrans\" 0.45 "
      "\"rgb scatterdistance\" [0 0 0] \"bool thin\" \"false\"\n"
      "Shape \"sphere\"\n"  // 1: as given
      "Texture \"t\" \"color\" \"checkerboard\"\nMaterial \"disney\" \"texture color\" \"t\"\n"
      "Shape \"sphere\"\n"                                                        // 2: a textured colour
      "Material \"disney\"\nShape \"sphere\" \"float metallic\" 0.75\n"  // 3: the shape's own value
      "Texture \"half\" \"float\" \"constant\" \"float value\" 0.5\n"
      "Material \"disney\" \"texture sheen\" \"half\"\nShape \"sphere\"\n"  // 4: a constant float texture
      "Texture \"bumps\" \"float\" \"fbm\"\n"
      "Material \"disney\" \"texture bumpmap\" \"bumps\"\nShape \"sphere\""));  // 5: a bump map
  const Scene& s = scene.scene;
  ASSERT_EQ(s.shapes.size(), 6u);
  auto disney = [&](size_t shape) { return as<DisneyMaterial>(s.materials.at(s.shapes[shape].material)); };
  const DisneyMaterial d = disney(0);
  EXPECT_EQ(sg::raw(d.diffuse.value), glm::vec3(0.5f));
  EXPECT_FALSE(d.diffuse.textured());
  EXPECT_EQ(d.metallic, 0.0f);
  EXPECT_EQ(d.eta, 1.5f);
  EXPECT_EQ(d.roughness, 0.5f);
  EXPECT_EQ(d.specular_tint, 0.0f);
  EXPECT_EQ(d.anisotropic, 0.0f);
  EXPECT_EQ(d.sheen, 0.0f);
  EXPECT_EQ(d.sheen_tint, 0.5f);
  EXPECT_EQ(d.clearcoat, 0.0f);
  EXPECT_EQ(d.clearcoat_gloss, 1.0f);
  EXPECT_EQ(d.spec_trans, 0.0f);
  const DisneyMaterial g = disney(1);
  EXPECT_EQ(sg::raw(g.diffuse.value), glm::vec3(0.2f, 0.3f, 0.4f));
  EXPECT_EQ(g.metallic, 0.25f);
  EXPECT_EQ(g.eta, 1.33f);
  EXPECT_EQ(g.roughness, 0.7f);
  EXPECT_EQ(g.specular_tint, 0.1f);
  EXPECT_EQ(g.sheen, 0.6f);
  EXPECT_EQ(g.sheen_tint, 0.2f);
  EXPECT_EQ(g.clearcoat, 0.9f);
  EXPECT_EQ(g.clearcoat_gloss, 0.35f);
  EXPECT_EQ(g.spec_trans, 0.45f);
  EXPECT_EQ(disney(2).diffuse.pattern, 0);
  EXPECT_EQ(diffuse(s.materials.at(s.shapes[2].material)).pattern, 0);  // what the integrator's textures look up
  EXPECT_EQ(disney(3).metallic, 0.75f);
  EXPECT_EQ(disney(4).sheen, 0.5f);
  EXPECT_FALSE(s.materials.at(s.shapes[4].material).bump.has_value());
  const std::optional<BumpMap>& bump = s.materials.at(s.shapes[5].material).bump;
  ASSERT_TRUE(bump.has_value());
  EXPECT_EQ(bump->pattern, 1);  // the fbm, after the checkerboard
  EXPECT_EQ(scene.warnings, "");
}

TEST(PbrtImport, DisneyRefusesWhatItDoesNotModel) {
  EXPECT_EQ(import_error(world(used("Material \"disney\" \"float anisotropic\" 0.5"))),
            "scene.pbrt:2:19: error: an anisotropic Material \"disney\" (\"anisotropic\" 0.5) is not supported\n"
            "Material \"disney\" \"float anisotropic\" 0.5\n                  ^~~~~~~~~~~~~~~~~~~\n"
            "help: the renderer's shading frames have no surface tangent (pbrt-v3's dp/du) to orient the lobe by; "
            "\"anisotropic\" 0 is isotropic\n");
  EXPECT_EQ(import_error(world(used("Material \"disney\" \"bool thin\" \"true\" \"float difftrans\" 2.5"))),
            "scene.pbrt:2:38: error: \"difftrans\" of Material \"disney\" must lie in [0, 2], found 2.5\n"
            "Material \"disney\" \"bool thin\" \"true\" \"float difftrans\" 2.5\n"
            "                                     ^~~~~~~~~~~~~~~~~\n");
  EXPECT_EQ(import_error(world(used("Material \"disney\" \"rgb scatterdistance\" [0.1 0.1 0.1]"))),
            "scene.pbrt:2:19: error: subsurface scattering (\"scatterdistance\") of Material \"disney\" is not supported\n"
            "Material \"disney\" \"rgb scatterdistance\" [0.1 0.1 0.1]\n                  ^~~~~~~~~~~~~~~~~~~~~\n"
            "help: pbrt-v3 renders the diffuse part by its BSSRDF there; a black \"scatterdistance\" (the default) is "
            "Burley's diffuse\n");
  EXPECT_EQ(import_error(world(used("Material \"disney\" \"float metallic\" 1.5"))),
            "scene.pbrt:2:19: error: \"metallic\" of Material \"disney\" must lie in [0, 1], found 1.5\n"
            "Material \"disney\" \"float metallic\" 1.5\n                  ^~~~~~~~~~~~~~~~\n");
  EXPECT_EQ(import_error(world("Texture \"f\" \"float\" \"fbm\"\n" + used("Material \"disney\" \"texture roughness\" \"f\""))),
            "scene.pbrt:3:19: error: a procedural texture as \"roughness\" of Material \"disney\" is not supported\n"
            "Material \"disney\" \"texture roughness\" \"f\"\n                  ^~~~~~~~~~~~~~~~~~~\n"
            "help: \"disney\" reads its float parameters as numbers here; \"color\" and \"bumpmap\" take textures\n");
}

// "thin": "flatness" 0, "difftrans" 1 by default.
TEST(PbrtImport, DisneyThin) {
  PbrtScene scene = import(world(used("Material \"disney\" \"bool thin\" \"true\"") + "\n" +
                                 used("Material \"disney\" \"bool thin\" \"true\" \"float flatness\" 0.4 "
                                      "\"float difftrans\" 1.5")));
  const Scene& s = scene.scene;
  ASSERT_EQ(s.shapes.size(), 2u);
  const DisneyMaterial defaults = as<DisneyMaterial>(s.materials.at(s.shapes[0].material));
  EXPECT_TRUE(defaults.thin);
  EXPECT_EQ(defaults.flatness, 0.0f);
  EXPECT_EQ(defaults.diff_trans, 1.0f);
  const DisneyMaterial given = as<DisneyMaterial>(s.materials.at(s.shapes[1].material));
  EXPECT_EQ(given.flatness, 0.4f);
  EXPECT_EQ(given.diff_trans, 1.5f);
  EXPECT_FALSE(as<DisneyMaterial>(import(world(used("Material \"disney\""))).scene.materials.at(0)).thin);
  EXPECT_EQ(scene.warnings, "");
}

// pbrt-v3 reads "flatness" and "difftrans" for thin surfaces only: a warning.
TEST(PbrtImport, DisneyWarnsOfThinParametersOnASolid) {
  PbrtScene scene = import(world(used("Material \"disney\" \"float flatness\" 0.5 \"float difftrans\" 0.2")));
  EXPECT_EQ(scene.warnings,
            "scene.pbrt:2:19: warning: parameter \"float flatness\" of Material \"disney\" is not used: it applies to "
            "thin surfaces (\"bool thin\" true) only\n"
            "Material \"disney\" \"float flatness\" 0.5 \"float difftrans\" 0.2\n                  ^~~~~~~~~~~~~~~~\n"
            "help: pbrt-v3 ignores it too without \"thin\"\n"
            "scene.pbrt:2:40: warning: parameter \"float difftrans\" of Material \"disney\" is not used: it applies to "
            "thin surfaces (\"bool thin\" true) only\n"
            "Material \"disney\" \"float flatness\" 0.5 \"float difftrans\" 0.2\n"
            "                                       ^~~~~~~~~~~~~~~~~\n"
            "help: pbrt-v3 ignores it too without \"thin\"\n");
}

// Its interface has index eta inside: meshes are wound as glass's, and a
// sphere under ReverseOrientation is refused as a glass one is; eta 1 has no outside.
TEST(PbrtImport, DisneyHasAnOutsideUnlessEtaIsOne) {
  EXPECT_NE(import_error(world("ReverseOrientation\n" + used("Material \"disney\""))), "");
  EXPECT_NO_THROW(import(world("ReverseOrientation\n" + used("Material \"disney\" \"float eta\" 1"))));
}

}  // namespace
}  // namespace safegi::render
