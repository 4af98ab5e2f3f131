// Whole renders of pbrt-v3's disney material: a sheet of it filling a narrow
// view in a uniform sky of radiance 1 shows its albedo towards the camera,
// ∫ f |cos θi| dωi over both sides (the sky behind comes through where it
// transmits), under every estimator knob: the integrator's light samples
// (below the surface too) and BSDF samples, weighed by MIS, agree with the BSDF.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "materials/bsdf.hpp"
#include "materials/bsdf_test_support.hpp"
#include "render_test_support.hpp"
#include "safegi/cpu_renderer/pbrt_import.hpp"

namespace safegi::render {
namespace {

using namespace test_support;

TEST(RenderDisney, SheetInAUniformSkyShowsItsAlbedo) {
  const std::string sets[] = {
      "\"float roughness\" 0.5",
      "\"float metallic\" 0.6 \"float roughness\" 0.4 \"float clearcoat\" 1 \"float clearcoatgloss\" 0.2 "
      "\"float sheen\" 1",
      "\"float spectrans\" 0.7 \"float roughness\" 0.6 \"float eta\" 1.4",
      "\"bool thin\" \"true\" \"float flatness\" 0.5 \"float difftrans\" 0.8 \"float spectrans\" 0.3 "
      "\"float roughness\" 0.7",
  };
  for (const std::string& parameters : sets) {
    PbrtImportOptions options;
    options.metres_per_unit = 1;
    PbrtScene imported = parse_pbrt_scene(
        "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 1\n"
        "Film \"image\" \"integer xresolution\" 8 \"integer yresolution\" 8\nWorldBegin\n"
        "LightSource \"infinite\" \"rgb L\" [1 1 1]\n"
        "Material \"disney\" \"rgb color\" [0.8 0.5 0.3] " + parameters + "\n"
        "Shape \"trianglemesh\" \"point P\" [-10 -10 0  10 -10 0  10 10 0  -10 10 0] \"integer indices\" [0 1 2 0 2 3]\n"
        "WorldEnd\n",
        "scene.pbrt", ".", options);
    const Scene& scene = imported.scene;
    ASSERT_EQ(scene.shapes.size(), 1u);
    const Shape& sheet = scene.shapes[0];
    // The side the camera (on +z) sees: the winding's (glass's, with η ≠ 1).
    const glm::dvec3 p0(sg::raw(sheet.positions[sheet.indices[0]])), p1(sg::raw(sheet.positions[sheet.indices[1]])),
        p2(sg::raw(sheet.positions[sheet.indices[2]]));
    const bool from_inside = glm::cross(p1 - p0, p2 - p0).z < 0;
    const Material& material = scene.materials.at(sheet.material);
    const Reflectance colour = diffuse_of(material)->value;
    const Bsdf bsdf(material, colour, from_inside);
    const DirectionShading wo(0, 0, 1);
    double albedo[3];
    for (int c = 0; c < 3; ++c)
      albedo[c] = bsdf_test::sphere_integral(
          [&](DirectionShading wi) { return sg::raw(bsdf.eval(wo, wi))[c] * std::abs(wi.z()); }, 1000, 180);
    for (const Knobs& knobs : estimator_knobs()) {
      const Image image = render_scene(scene, 256, 2, std::nullopt, knobs.apply);
      for (int c = 0; c < 3; ++c) {
        const Estimate estimate = channel_estimate(image, c);
        EXPECT_NEAR(estimate.mean, albedo[c], 4 * estimate.standard_error + 5e-3 * albedo[c])
            << parameters << ", channel " << c << ", " << knobs.name;
      }
    }
  }
}

}  // namespace
}  // namespace safegi::render
