// pbrt-v3's participating media as the importer reads them: MakeNamedMedium's
// coefficients per metre, MediumInterface's sides on each shape (on pbrt-v3's
// geometric normal's side), the camera's medium, invisible surfaces, and
// pbrt-v3's rule that only volpath, bdpt and mlt render media.
#include <gtest/gtest.h>

#include <string>

#include "pbrt/pbrt_import_test_support.hpp"

namespace safegi::render {
namespace {

using namespace pbrt_test;

const char* const kFog =
    "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"rgb sigma_a\" [0.02 0.03 0.04] "
    "\"rgb sigma_s\" [0.3 0.4 0.5] \"float g\" 0.25 \"float scale\" 2\n";

std::string first_line_of(const std::string& text) { return text.substr(0, text.find('\n')); }

double channel(const spectrum<dim::inv_length>& s, int c) { return sg::raw(s[c]); }

TEST(PbrtImportMedia, HomogeneousMediumPerMetre) {
  // One scene unit is 0.5 m: a coefficient per unit is twice that per metre.
  PbrtScene scene = import(std::string("Integrator \"volpath\"\n") + kFog + "MediumInterface \"\" \"fog\"\n" + world(""),
                           in_memory({}, 0.5));
  ASSERT_EQ(scene.scene.media.size(), 1u);
  const Medium& fog = scene.scene.media[0];
  EXPECT_EQ(fog.name, "fog");
  EXPECT_FLOAT_EQ(fog.asymmetry, 0.25f);
  const double absorption[] = {0.02, 0.03, 0.04}, scattering[] = {0.3, 0.4, 0.5};
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(channel(fog.absorption, c), absorption[c] * 2 / 0.5, 1e-6) << c;
    EXPECT_NEAR(channel(fog.scattering, c), scattering[c] * 2 / 0.5, 1e-6) << c;
  }
  EXPECT_EQ(scene.scene.camera.medium, 0);  // the outside medium at WorldEnd, as pbrt-v3's MakeCamera
  EXPECT_EQ(scene.warnings, "");
}

TEST(PbrtImportMedia, PbrtV3Defaults) {
  PbrtScene scene = import("Integrator \"volpath\"\nMakeNamedMedium \"m\" \"string type\" \"homogeneous\"\n"
                           "MediumInterface \"m\"\n" +
                           world(""));
  const Medium& m = scene.scene.media.at(0);
  EXPECT_FLOAT_EQ(m.asymmetry, 0.0f);
  EXPECT_NEAR(channel(m.absorption, 2), 0.014, 1e-7);
  EXPECT_NEAR(channel(m.scattering, 0), 2.55, 1e-6);
  EXPECT_EQ(scene.scene.camera.medium, 0);  // one name is both sides
}

// A shape takes the media of the graphics state it is made in (attributes
// scope them); where the two sides agree it is no boundary.
TEST(PbrtImportMedia, ShapesBoundTheMediaOfTheirGraphicsState) {
  PbrtScene scene = import(std::string("Integrator \"volpath\"\n") + kFog +
                           world("AttributeBegin\nMediumInterface \"fog\" \"\"\nMaterial \"\"\n"
                                 "Shape \"sphere\" \"float radius\" 2\nAttributeEnd\n"
                                 "Shape \"sphere\" \"float radius\" 0.5\n"
                                 "AttributeBegin\nReverseOrientation\nMediumInterface \"fog\" \"\"\n"
                                 "Shape \"sphere\" \"float radius\" 3\nAttributeEnd\n"
                                 "MediumInterface \"fog\" \"fog\"\nShape \"sphere\""));
  const std::vector<Shape>& shapes = scene.scene.shapes;
  ASSERT_EQ(shapes.size(), 4u);
  EXPECT_TRUE(shapes[0].invisible);
  ASSERT_TRUE(shapes[0].media);
  EXPECT_EQ(shapes[0].media->inside, 0);
  EXPECT_EQ(shapes[0].media->outside, -1);
  EXPECT_FALSE(shapes[1].invisible);
  EXPECT_FALSE(shapes[1].media);
  // Turned inside out: pbrt-v3's outside is our sphere's inside.
  ASSERT_TRUE(shapes[2].media);
  EXPECT_EQ(shapes[2].media->inside, -1);
  EXPECT_EQ(shapes[2].media->outside, 0);
  EXPECT_FALSE(shapes[3].media);
  EXPECT_EQ(scene.scene.camera.medium, 0);  // the last MediumInterface's outside
}

// pbrt-v3's outside is its geometric normal's side: a mesh is wound so that ours is the same.
TEST(PbrtImportMedia, MeshesAreWoundSoThatOutsideIsPbrtV3s) {
  const std::string floor =
      "Shape \"trianglemesh\" \"integer indices\" [0 1 2 2 3 0] \"point P\" [-1 0 -1 1 0 -1 1 0 1 -1 0 1]";
  PbrtScene scene = import(std::string("Integrator \"volpath\"\n") + kFog + world("MediumInterface \"\" \"fog\"\n" + floor));
  const Shape& shape = scene.scene.shapes.at(0);
  ASSERT_TRUE(shape.media);
  EXPECT_EQ(shape.media->outside, 0);
  // pbrt-v3's normal of this winding, Cross(p0 - p2, p1 - p2), is −y (down);
  // our world mirrors x, which keeps y.
  const uint32_t* v = shape.indices.data();
  vector<World> e1 = sg::from_raw<PointWorld>(sg::raw(shape.positions[v[1]])) -
                     sg::from_raw<PointWorld>(sg::raw(shape.positions[v[0]]));
  vector<World> e2 = sg::from_raw<PointWorld>(sg::raw(shape.positions[v[2]])) -
                     sg::from_raw<PointWorld>(sg::raw(shape.positions[v[0]]));
  EXPECT_LT(sg::raw(sg::cross(e1, e2)).y, 0);
}

// pbrt-v3 renders media only under volpath, bdpt and mlt; under any other
// integrator it renders without them (it warns), and so do we. A boundary
// with no surface is then nothing at all.
TEST(PbrtImportMedia, OtherIntegratorsRenderWithoutMediaAsPbrtV3) {
  const std::string body = "MediumInterface \"fog\" \"\"\nMaterial \"\"\nShape \"sphere\"\nMaterial \"matte\"\n"
                           "Shape \"sphere\" \"float radius\" 0.5";
  PbrtScene scene = import(std::string("Integrator \"path\"\n") + kFog + world(body));
  EXPECT_TRUE(scene.scene.media.empty());
  EXPECT_EQ(scene.scene.camera.medium, -1);
  ASSERT_EQ(scene.scene.shapes.size(), 1u);
  EXPECT_FALSE(scene.scene.shapes[0].media);
  EXPECT_FALSE(scene.scene.has_media());
  EXPECT_EQ(scene.warnings,
            "scene.pbrt:1:12: warning: the scene has participating media, which pbrt-v3's integrator \"path\" does not "
            "trace: rendering without them, as pbrt-v3 does\n"
            "Integrator \"path\"\n           ^~~~~~\n"
            "help: \"volpath\", \"bdpt\" or \"mlt\" render them (here: the path tracer, which traces them)\n");
  PbrtScene bdpt = import(std::string("Integrator \"bdpt\"\n") + kFog + world(body));
  EXPECT_EQ(bdpt.scene.media.size(), 1u);
  EXPECT_EQ(bdpt.scene.shapes.size(), 2u);
  // Ours does not trace media bidirectionally yet: the path tracer renders them, saying so.
  EXPECT_EQ(bdpt.scene.settings.integrator, IntegratorType::path);
  EXPECT_NE(bdpt.warnings.find("integrator \"bdpt\": bdpt cannot render this scene (the scene has participating media "
                               "or invisible surfaces): rendering with \"path\""),
            std::string::npos)
      << bdpt.warnings;
}

TEST(PbrtImportMedia, ErrorsNameTheParameter) {
  EXPECT_EQ(import_error(world("MediumInterface \"smoke\" \"\"\nShape \"sphere\"")),
            "scene.pbrt:2:17: error: no medium named \"smoke\"\n"
            "MediumInterface \"smoke\" \"\"\n                ^~~~~~~\n"
            "help: MakeNamedMedium defines one, before the shapes that use it\n");
  EXPECT_EQ(import_error("MakeNamedMedium \"m\" \"string type\" \"heterogeneous\"\n" + world("")),
            "scene.pbrt:1:21: error: a heterogeneous medium (a density grid) is not supported\n"
            "MakeNamedMedium \"m\" \"string type\" \"heterogeneous\"\n"
            "                    ^~~~~~~~~~~~~\n"
            "help: supported: \"homogeneous\"\n");
  EXPECT_EQ(first_line_of(import_error("MakeNamedMedium \"m\" \"string type\" \"homogeneous\" \"float g\" 1\n" + world(""))),
            "scene.pbrt:1:49: error: \"g\" of MakeNamedMedium \"m\" must lie in (-1, 1), found 1");
  EXPECT_EQ(first_line_of(import_error("MakeNamedMedium \"m\" \"string type\" \"homogeneous\" \"rgb sigma_s\" [1 -1 1]\n" +
                                       world(""))),
            "scene.pbrt:1:49: error: \"sigma_s\" of MakeNamedMedium \"m\" must not be negative, found -1 in a channel");
  EXPECT_EQ(first_line_of(import_error("MakeNamedMedium \"m\" \"string type\" \"homogeneous\" \"string preset\" \"Apple\"\n" +
                                       world(""))),
            "scene.pbrt:1:49: error: \"string preset\" of MakeNamedMedium \"m\" is not supported: give \"sigma_a\" and "
            "\"sigma_s\" instead: pbrt-v3's table of measured media is not here");
  EXPECT_EQ(first_line_of(import_error("MakeNamedMedium \"m\"\n" + world(""))),
            "scene.pbrt:1:17: error: MakeNamedMedium \"m\" has no \"string type\"");
}

}  // namespace
}  // namespace safegi::render
