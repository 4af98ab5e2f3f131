// pbrt-v3's goniometric and projection lights as the importer reads them
// (src/lights/goniometric.cpp, projection.cpp): "I" × "scale", at the light
// transform's origin, shaped by "mapname" in the light's frame; projection's
// "fov" (default 45); a map read as it is (pbrt-v3 decodes no gamma there).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pbrt/pbrt_import_test_support.hpp"

namespace safegi::render {
namespace {

using namespace pbrt_test;

// "gonio.exr": 4 × 2, the top row 1 and the bottom row 0.25 (θ below or above π/2).
PbrtImportOptions with_map(double metres = 1) {
  PbrtImportOptions options = in_memory({}, metres);
  options.read_image = [](const std::filesystem::path& path) {
    if (path.filename() != "gonio.exr") throw std::runtime_error("no such file");
    Image image;
    image.width = 4, image.height = 2;
    image.rgb.assign(12, 1.0f);
    image.rgb.resize(24, 0.25f);
    return image;
  };
  return options;
}

DirectionWorld direction_of(double x, double y, double z) {
  return sg::normalize(sg::from_raw<vector<World, dim::dimensionless>>(
      sg::vec3_rep(static_cast<Real>(x), static_cast<Real>(y), static_cast<Real>(z))));
}

TEST(PbrtImportLights, GoniometricIsAPointLightShapedByItsMap) {
  PbrtScene scene = import(world("Translate 1 2 3\nRotate 90 1 0 0\n"
                                 "LightSource \"goniometric\" \"rgb I\" [2 4 6] \"rgb scale\" [0.5 0.5 0.5] "
                                 "\"string mapname\" \"gonio.exr\""),
                           with_map(0.1));
  ASSERT_EQ(scene.scene.point_lights.size(), 1u);
  const PointLight& light = scene.scene.point_lights[0];
  const sg::vec3_rep at = sg::raw(light.position - PointWorld{});
  EXPECT_NEAR(std::fabs(at.x), 0.1, 1e-6);  // the world may be mirrored for the camera's handedness
  EXPECT_NEAR(at.y, 0.2, 1e-6);
  EXPECT_NEAR(at.z, 0.3, 1e-6);
  EXPECT_NEAR(sg::raw(light.intensity).z, 3 * 0.01, 1e-7);  // I × scale × (metres per unit)²
  ASSERT_TRUE(light.profile);
  EXPECT_EQ(light.profile->layout, IntensityMap::Layout::goniometric);
  EXPECT_EQ(light.profile->file, "gonio.exr");
  // Rotate 90 about x takes the map's pole (light +y) to world +z: +z is bright, −z dim.
  EXPECT_NEAR(sg::raw(intensity_factor(*light.profile, direction_of(0, 0, 1))).x, 1.0, 1e-6);
  EXPECT_NEAR(sg::raw(intensity_factor(*light.profile, direction_of(0, 0, -1))).x, 0.25, 1e-6);
  EXPECT_EQ(scene.warnings, "");
}

TEST(PbrtImportLights, ProjectionReadsItsFieldOfView) {
  PbrtScene scene = import(world("LightSource \"projection\" \"float fov\" 30"));
  ASSERT_EQ(scene.scene.point_lights.size(), 1u);
  const IntensityMap& profile = *scene.scene.point_lights[0].profile;
  EXPECT_EQ(profile.layout, IntensityMap::Layout::projection);
  EXPECT_NEAR(sg::raw(profile.fov), 30 * std::numbers::pi / 180, 1e-6);
  EXPECT_FALSE(profile.map);  // no map: texels of 1 inside a square window, as in pbrt-v3
  const double inside = std::tan(14 * std::numbers::pi / 180), outside = std::tan(16 * std::numbers::pi / 180);
  EXPECT_EQ(sg::raw(intensity_factor(profile, direction_of(inside, -inside, 1))).y, 1.0f);
  EXPECT_EQ(sg::raw(intensity_factor(profile, direction_of(outside, 0, 1))).y, 0.0f);
  EXPECT_EQ(sg::raw(intensity_factor(profile, direction_of(0, 0, -1))).y, 0.0f);  // behind it
  EXPECT_NEAR(sg::raw(import(world("LightSource \"projection\"")).scene.point_lights[0].profile->fov),
              std::numbers::pi / 4, 1e-6);
}

TEST(PbrtImportLights, MappedLightErrors) {
  EXPECT_EQ(first_line(import_error(world("LightSource \"projection\" \"float fov\" 180"))),
            "scene.pbrt:2:1: error: \"float fov\" must lie in (0, 180) degrees");
  EXPECT_EQ(first_line(import_error(world("Scale 1 2 1\nLightSource \"goniometric\""))),
            "scene.pbrt:3:1: error: a goniometric light under a transform that scales unevenly or shears is not "
            "supported");
  EXPECT_EQ(first_line(import_error(world("LightSource \"goniometric\" \"string mapname\" \"missing.exr\""), with_map())),
            "scene.pbrt:2:44: error: cannot read image 'dir/missing.exr': no such file");
  // pbrt-v3's goniometric light has no "from": it is placed by the transform alone.
  EXPECT_NE(import(world("LightSource \"goniometric\" \"point from\" [0 1 0]")).warnings.find(
                "parameter \"point from\" of LightSource \"goniometric\" is not used"),
            std::string::npos);
}

// The mean factor over the sphere (the light's power over 4π I): a square
// window of 90° is a cube's face, 1/6 of the sphere; a lat-long map's rows
// count by the solid angle they cover.
TEST(PbrtImportLights, MeanFactorIsTheMapOverTheSphere) {
  PbrtScene cube_face = import(world("LightSource \"projection\" \"float fov\" 90"));
  EXPECT_NEAR(sg::raw(mean_intensity_factor(*cube_face.scene.point_lights[0].profile)).x, 1.0 / 6, 1e-6);
  PbrtScene gonio = import(world("LightSource \"goniometric\" \"string mapname\" \"gonio.exr\""), with_map());
  EXPECT_NEAR(sg::raw(mean_intensity_factor(*gonio.scene.point_lights[0].profile)).x, 0.5 * (1 + 0.25), 1e-6);
}

}  // namespace
}  // namespace safegi::render

namespace safegi::render {
namespace {

using namespace pbrt_test;

// Emitters for the light-choice tests: a disk (one pbrt-v3 light), a two-triangle
// mesh (two lights in pbrt-v3) and an infinite light, each asking for nsamples.
constexpr const char* kEmitters =
    "AttributeBegin\nAreaLightSource \"diffuse\" \"integer nsamples\" 16\nShape \"disk\"\nAttributeEnd\n"
    "AttributeBegin\nAreaLightSource \"diffuse\" \"integer nsamples\" 4\n"
    "Shape \"trianglemesh\" \"point P\" [0 0 1 1 0 1 1 1 1 0 1 1] \"integer indices\" [0 1 2 0 2 3]\nAttributeEnd\n"
    "LightSource \"infinite\" \"integer samples\" 3\n";

TEST(PbrtImportLights, DirectLightingSamplesEveryLightItsNsamplesTimes) {
  PbrtScene scene = import("Integrator \"directlighting\"\n" + world(kEmitters));
  EXPECT_EQ(scene.scene.settings.integrator, IntegratorType::direct);
  EXPECT_EQ(scene.scene.settings.light_strategy, LightStrategy::all);
  ASSERT_EQ(scene.scene.shapes.size(), 2u);
  EXPECT_EQ(scene.scene.shapes[0].emission_samples, 16);
  EXPECT_EQ(scene.scene.shapes[1].emission_samples, 8);  // 4 for each of pbrt-v3's two triangle lights
  ASSERT_TRUE(scene.scene.environment.has_value());
  EXPECT_EQ(scene.scene.environment->samples, 3);
  EXPECT_EQ(import("Integrator \"directlighting\" \"string strategy\" \"one\"\n" + world(kEmitters)).scene.settings.light_strategy,
            LightStrategy::uniform);
}

TEST(PbrtImportLights, WhittedSamplesEveryLightOnce) {
  PbrtScene scene = import("Integrator \"whitted\"\n" + world(kEmitters));
  EXPECT_EQ(scene.scene.settings.light_strategy, LightStrategy::all);
  EXPECT_EQ(scene.scene.shapes[0].emission_samples, 1);
  EXPECT_EQ(scene.scene.shapes[1].emission_samples, 2);
  EXPECT_EQ(scene.scene.environment->samples, 1);
}

// Exporters write `"string mapname" [ "" ]` for a light without a map; pbrt-v3
// reads an empty name as none (no file "./" to read).
TEST(PbrtImportLights, AnEmptyMapNameIsNoMap) {
  PbrtScene infinite = import(world("LightSource \"infinite\" \"rgb L\" [2 2 2] \"string mapname\" [ \"\" ]"), with_map());
  ASSERT_TRUE(infinite.scene.environment.has_value());
  EXPECT_FALSE(infinite.scene.environment->map);
  EXPECT_EQ(infinite.scene.environment->file, "");
  EXPECT_EQ(sg::raw(infinite.scene.environment->radiance), glm::vec3(2));
  EXPECT_EQ(infinite.warnings, "");
  for (const char* type : {"goniometric", "projection"}) {
    PbrtScene mapped = import(world("LightSource \"" + std::string(type) + "\" \"string mapname\" \"\""), with_map());
    ASSERT_EQ(mapped.scene.point_lights.size(), 1u) << type;
    ASSERT_TRUE(mapped.scene.point_lights[0].profile) << type;
    EXPECT_FALSE(mapped.scene.point_lights[0].profile->map) << type;
    EXPECT_EQ(mapped.warnings, "") << type;
  }
}

// Exporters place lights with rotations rounded to 4 significant digits, as
// they do cameras: the nearest rotation, with a warning; a shear is still refused.
TEST(PbrtImportLights, ARotationRoundedByAnExporterTurnsAMapWithAWarning) {
  // Rotate 30 about z, rounded: cos 30° = 0.8660254, sin 30° = 0.5.
  const std::string rounded = "Transform [0.866 0.5 0 0  -0.5 0.866 0 0  0 0 1 0  0 0 0 1]\n";
  for (const char* light : {"LightSource \"infinite\"", "LightSource \"goniometric\"", "LightSource \"spot\""}) {
    PbrtScene scene = import(world(rounded + light));
    EXPECT_NE(scene.warnings.find("is a rotation only to within 2.9e-05: rendered with the nearest rotation"),
              std::string::npos)
        << light << ": " << scene.warnings;
  }
  PbrtScene scene = import(world(rounded + "LightSource \"infinite\""));
  // Light +x goes to pbrt's (cos 30°, sin 30°, 0), which the mirrored import world has at x < 0.
  const glm::vec3 x = sg::raw(scene.scene.environment->render_from_light(direction<LightSpace>(1, 0, 0)));
  EXPECT_NEAR(x.x, -std::cos(std::numbers::pi / 6), 1e-4);
  EXPECT_NEAR(x.y, 0.5, 1e-4);
  EXPECT_NEAR(glm::length(x), 1.0f, 1e-6f);
  EXPECT_EQ(first_line(import_error(world("ConcatTransform [1 0 0 0  0.05 1 0 0  0 0 1 0  0 0 0 1]\n"
                                          "LightSource \"infinite\""))),
            "scene.pbrt:3:1: error: an infinite light under a transform that scales unevenly or shears is not supported");
  EXPECT_EQ(first_line(import_error(world("Scale 0 0 0\nLightSource \"spot\""))),
            "scene.pbrt:3:1: error: a spot light under a transform that scales unevenly or shears is not supported");
}

TEST(PbrtImportLights, PathChoosesLightsAsItsLightSampleStrategySays) {
  EXPECT_EQ(import(world("")).scene.settings.light_strategy, LightStrategy::spatial);  // pbrt-v3's default integrator
  for (auto [name, strategy] : {std::pair{"uniform", LightStrategy::uniform}, std::pair{"power", LightStrategy::power},
                                std::pair{"spatial", LightStrategy::spatial}})
    EXPECT_EQ(import("Integrator \"volpath\" \"string lightsamplestrategy\" \"" + std::string(name) + "\"\n" + world(""))
                  .scene.settings.light_strategy,
              strategy);
  PbrtScene unknown = import("Integrator \"path\" \"string lightsamplestrategy\" \"best\"\n" + world(""));
  EXPECT_EQ(unknown.scene.settings.light_strategy, LightStrategy::spatial);
  EXPECT_NE(unknown.warnings.find("unknown \"string lightsamplestrategy\" \"best\": using \"spatial\", as pbrt-v3 does"),
            std::string::npos)
      << unknown.warnings;
}

}  // namespace
}  // namespace safegi::render
