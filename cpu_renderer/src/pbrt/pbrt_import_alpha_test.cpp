// pbrt-v3's alpha masks as the importer reads them (src/shapes/triangle.cpp,
// plymesh.cpp: "alpha" and "shadowalpha", a float or a float texture, on
// triangle meshes only), and its dots texture, whose "inside" and "outside"
// pbrt-v3 passes to its constructor in swapped order.
#include <gtest/gtest.h>

#include "pbrt/pbrt_import_test_support.hpp"

namespace safegi::render {
namespace {

using namespace pbrt_test;

const char* const kTriangle = "Shape \"trianglemesh\" \"point P\" [0 0 0 1 0 0 0 1 0] ";

TEST(PbrtImportAlpha, MasksAreFloatsOrFloatTextures) {
  PbrtScene scene = import(world(std::string("Texture \"holes\" \"float\" \"dots\" \"float uscale\" 10\n") +
                                 kTriangle + "\"float alpha\" 0\n" +                    // 0: invisible
                                 kTriangle + "\"float alpha\" 0.5\n" +                  // no mask: only 0 masks
                                 kTriangle + "\"texture alpha\" \"holes\"\n" +          // 2
                                 kTriangle + "\"float shadowalpha\" 0\n"));             // 3: casts no shadow
  const std::vector<Shape>& shapes = scene.scene.shapes;
  ASSERT_EQ(shapes.size(), 4u);
  ASSERT_TRUE(shapes[0].alpha);
  EXPECT_FALSE(shapes[0].alpha->textured());
  EXPECT_EQ(sg::raw(shapes[0].alpha->value).x, 0.0f);
  EXPECT_FALSE(shapes[0].shadow_alpha);
  EXPECT_FALSE(shapes[1].alpha);
  ASSERT_TRUE(shapes[2].alpha);
  EXPECT_GE(shapes[2].alpha->pattern, 0);
  EXPECT_FALSE(shapes[3].alpha);
  ASSERT_TRUE(shapes[3].shadow_alpha);
  EXPECT_EQ(scene.warnings, "");
}

TEST(PbrtImportAlpha, OnlyTriangleMeshesReadMasks) {
  // pbrt-v3 reads no mask on a sphere: the parameter is unused there, as here.
  PbrtScene sphere = import(world("Shape \"sphere\" \"float alpha\" 0"));
  EXPECT_FALSE(sphere.scene.shapes[0].alpha);
  EXPECT_NE(sphere.warnings.find("parameter \"float alpha\" of Shape \"sphere\" is not used"), std::string::npos);
  EXPECT_EQ(first_line(import_error(world(std::string(kTriangle) + "\"texture alpha\" \"nowhere\""))),
            "scene.pbrt:2:68: error: no float texture named \"nowhere\"");
}

TEST(PbrtImportAlpha, DotsShowOutsideInTheDotsAsPbrtV3Does) {
  PbrtScene scene = import(world(used_texture("Texture \"t\" \"color\" \"dots\" \"rgb inside\" [0.1 0.2 0.3] "
                                              "\"rgb outside\" [0.7 0.8 0.9]")));
  ASSERT_EQ(scene.scene.patterns.size(), 1u);
  const auto& dots = std::get<DotsPattern>(scene.scene.patterns[0].pattern);
  EXPECT_EQ(sg::raw(dots.inside), glm::vec3(0.7f, 0.8f, 0.9f));  // in the dots: pbrt-v3's "outside"
  EXPECT_EQ(sg::raw(dots.outside), glm::vec3(0.1f, 0.2f, 0.3f));
}

}  // namespace
}  // namespace safegi::render
