// pbrt-v3's translucent material as the importer reads it: the parameters and
// defaults of its CreateTranslucentMaterial (src/materials/translucent.cpp),
// when it adds no BxDF (black), the bound on what it scatters, and what is
// refused as for the other materials.
#include <gtest/gtest.h>

#include "pbrt/pbrt_import_test_support.hpp"

namespace safegi::render {
namespace {

using namespace pbrt_test;

// "Kd" 0.25 (constant or texture), "Ks" 0.25, "reflect" 0.5, "transmit" 0.5,
// "roughness" 0.1, "remaproughness" true (RoughnessToAlpha, then
// TrowbridgeReitzDistribution's floor of 0.001); the interface's index is 1.5.
TEST(PbrtImport, TranslucentAsPbrtV3DefinesIt) {
  PbrtScene scene = import(world(
      "Material \"translucent\"\nShape \"sphere\"\n"  // 0: pbrt-v3's defaults
      "Material \"translucent\" \"rgb Kd\" [0.2 0.3 0.4] \"rgb Ks\" [0.1 0.2 0.3] \"rgb reflect\" [0.3 0.2 0.1] "
      "\"rgb transmit\" [0.6 0.7 0.8] \"float roughness\" 0.3 \"bool remaproughness\" \"false\"\n"
      "Shape \"sphere\"\n"                                                         // 1: as given
      "Material \"translucent\" \"float roughness\" 0.2\nShape \"sphere\"\n"  // 2: remapped
      "Material \"translucent\" \"float roughness\" 0 \"bool remaproughness\" \"false\"\n"
      "Shape \"sphere\"\n"  // 3: the floor
      // 4: a textured Kd (the checkerboard's white squares: 1, times reflect + transmit: no more than 1)
      "Texture \"t\" \"color\" \"checkerboard\"\nMaterial \"translucent\" \"texture Kd\" \"t\" \"rgb Ks\" [0 0 0]\n"
      "Shape \"sphere\"\n"
      "Material \"translucent\" \"rgb reflect\" [0 0 0] \"rgb transmit\" [0 0 0]\nShape \"sphere\"\n"  // 5: no BxDF
      "Material \"translucent\" \"rgb Kd\" [0 0 0] \"rgb Ks\" [0 0 0]\nShape \"sphere\"\n"  // 6: no BxDF either
      "Material \"translucent\" \"rgb Kd\" [0 0 0]\nShape \"sphere\"\n"  // 7: the glossy lobes alone
      "Material \"translucent\"\nShape \"sphere\" \"rgb transmit\" [0.1 0.2 0.3]"));  // 8: the shape's own value
  const Scene& s = scene.scene;
  ASSERT_EQ(s.shapes.size(), 9u);
  auto translucent = [&](size_t shape) { return as<TranslucentMaterial>(s.materials.at(s.shapes[shape].material)); };
  EXPECT_EQ(sg::raw(translucent(0).diffuse.value), glm::vec3(0.25f));
  EXPECT_FALSE(translucent(0).diffuse.textured());
  EXPECT_EQ(sg::raw(translucent(0).specular), glm::vec3(0.25f));
  EXPECT_EQ(sg::raw(translucent(0).reflect), glm::vec3(0.5f));
  EXPECT_EQ(sg::raw(translucent(0).transmit), glm::vec3(0.5f));
  EXPECT_NEAR(translucent(0).alpha, pbrt_alpha(0.1), 1e-6);
  EXPECT_EQ(translucent(0).ior, 1.5f);
  EXPECT_EQ(sg::raw(translucent(1).diffuse.value), glm::vec3(0.2f, 0.3f, 0.4f));
  EXPECT_EQ(sg::raw(translucent(1).specular), glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(sg::raw(translucent(1).reflect), glm::vec3(0.3f, 0.2f, 0.1f));
  EXPECT_EQ(sg::raw(translucent(1).transmit), glm::vec3(0.6f, 0.7f, 0.8f));
  EXPECT_EQ(translucent(1).alpha, 0.3f);
  EXPECT_NEAR(translucent(2).alpha, pbrt_alpha(0.2), 1e-6);
  EXPECT_EQ(translucent(3).alpha, 0.001f);
  EXPECT_EQ(translucent(4).diffuse.pattern, 0);
  EXPECT_EQ(diffuse(s.materials.at(s.shapes[4].material)).pattern, 0);  // what the integrator's textures look up
  EXPECT_EQ(sg::raw(translucent(4).specular), glm::vec3(0));
  EXPECT_EQ(s.shapes[5].material, -1);
  EXPECT_EQ(s.shapes[6].material, -1);
  EXPECT_EQ(sg::raw(translucent(7).diffuse.value), glm::vec3(0));
  EXPECT_EQ(sg::raw(translucent(7).specular), glm::vec3(0.25f));
  EXPECT_EQ(sg::raw(translucent(8).transmit), glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(sg::raw(translucent(8).reflect), glm::vec3(0.5f));
  EXPECT_EQ(scene.warnings, "");
}

// Seen from outside, each part sends reflect + transmit of what it scatters,
// so (Kd + Ks)(reflect + transmit) bounds the whole: above 1 pbrt-v3 renders
// it all the same, and so do we, with a warning (a textured Kd by its
// largest texel). Reflectances beyond [0, 1] and textures elsewhere than Kd
// are refused as for the other materials; pbrt-v3's translucent reads one
// "roughness", no "uroughness".
TEST(PbrtImport, TranslucentBoundsAndRefusals) {
  PbrtScene bright = import(world(used("Material \"translucent\" \"rgb Kd\" [0.9 0.5 0.5] \"rgb Ks\" [0.3 0.1 0.1] "
                                       "\"rgb reflect\" [0.6 0.5 0.5] \"rgb transmit\" [0.6 0.5 0.5]")));
  EXPECT_EQ(first_line(bright.warnings),
            "scene.pbrt:2:10: warning: (\"Kd\" + \"Ks\") * (\"reflect\" + \"transmit\") of Material \"translucent\" "
            "exceeds 1 in a channel (1.44): the surface may scatter more light than it receives");
  EXPECT_TRUE(is<TranslucentMaterial>(bright.scene.materials.at(bright.scene.shapes[0].material)));
  // Kd + Ks = 1 and reflect + transmit = 1 is the bound itself: no warning.
  EXPECT_EQ(import(world(used("Material \"translucent\" \"rgb Kd\" [0.75 0.75 0.75] \"rgb reflect\" [0.25 0.25 0.25] "
                              "\"rgb transmit\" [0.75 0.75 0.75]")))
                .warnings,
            "");

  auto error_of = [](const std::string& material) { return first_line(import_error(world(used(material)))); };
  EXPECT_EQ(error_of("Material \"translucent\" \"rgb reflect\" [1.2 0.5 0.5]"),
            "scene.pbrt:2:24: error: \"reflect\" of Material \"translucent\" must lie in [0, 1] in every channel");
  EXPECT_EQ(error_of("Material \"translucent\" \"rgb transmit\" [0.5 -0.1 0.5]"),
            "scene.pbrt:2:24: error: \"transmit\" of Material \"translucent\" must lie in [0, 1] in every channel");
  EXPECT_EQ(error_of("Texture \"t\" \"color\" \"checkerboard\"\nMaterial \"translucent\" \"texture transmit\" \"t\""),
            "scene.pbrt:3:24: error: a procedural texture as \"transmit\" of Material \"translucent\" is not supported");
  EXPECT_EQ(error_of("Texture \"t\" \"color\" \"checkerboard\"\nMaterial \"translucent\" \"texture Ks\" \"t\""),
            "scene.pbrt:3:24: error: a procedural texture as \"Ks\" of Material \"translucent\" is not supported");
  PbrtScene anisotropic = import(world(used("Material \"translucent\" \"float uroughness\" 0.5")));
  EXPECT_NEAR(as<TranslucentMaterial>(anisotropic.scene.materials.at(anisotropic.scene.shapes[0].material)).alpha,
              pbrt_alpha(0.1), 1e-6);
  EXPECT_NE(anisotropic.warnings.find("parameter \"float uroughness\" of Material \"translucent\" is not used"),
            std::string::npos)
      << anisotropic.warnings;
}

// pbrt-v3's glass with "uroughness"/"vroughness" (remapped by default) is
// its two microfacet lobes, Kr and Kt, on an interface of index "eta":
// translucent's glossy lobes with Kd 0 and Ks 1; at roughness 0, smooth glass.
TEST(PbrtImport, RoughGlassIsTranslucentsGlossyLobes) {
  PbrtScene scene = import(world(
      "Material \"glass\" \"float uroughness\" 0.2 \"float vroughness\" 0.2 \"rgb Kr\" [0.9 0.8 0.7] "
      "\"float eta\" 1.33\nShape \"sphere\"\n"                                                                 // 0
      "Material \"glass\" \"float uroughness\" 0.05 \"float vroughness\" 0.05 \"bool remaproughness\" \"false\"\n"
      "Shape \"sphere\"\n"                                                                                      // 1
      "Material \"glass\" \"float uroughness\" 0 \"float vroughness\" 0\nShape \"sphere\""));                 // 2
  const Scene& s = scene.scene;
  ASSERT_EQ(s.shapes.size(), 3u);
  const TranslucentMaterial rough = as<TranslucentMaterial>(s.materials.at(s.shapes[0].material));
  EXPECT_TRUE(sg::is_black(rough.diffuse.value));
  EXPECT_EQ(sg::raw(rough.specular), glm::vec3(1));
  EXPECT_EQ(sg::raw(rough.reflect), glm::vec3(0.9f, 0.8f, 0.7f));
  EXPECT_EQ(sg::raw(rough.transmit), glm::vec3(1));
  EXPECT_NEAR(rough.alpha, pbrt_alpha(0.2), 1e-6);
  EXPECT_FLOAT_EQ(rough.ior, 1.33f);
  EXPECT_FLOAT_EQ(as<TranslucentMaterial>(s.materials.at(s.shapes[1].material)).alpha, 0.05f);
  EXPECT_TRUE(is<GlassMaterial>(s.materials.at(s.shapes[2].material)));
  EXPECT_EQ(scene.warnings, "");
  EXPECT_EQ(first_line(import_error(world(used("Material \"glass\" \"float uroughness\" 0.1 \"float vroughness\" 0.3")))),
            "scene.pbrt:2:10: error: an anisotropic Material \"glass\" (\"uroughness\" 0.1, \"vroughness\" 0.3) is not "
            "supported");
}

}  // namespace
}  // namespace safegi::render
