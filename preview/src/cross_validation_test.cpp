// The preview against the CPU renderer's direct-lighting integrator on the
// bundled scenes, at small resolutions. Each tolerance is about twice the
// difference measured when it was set (docs/preview.md, "Cross-validation"):
// the CPU images' own noise is 5-10x smaller, so what is left is the
// preview's approximation — shadow-map texels and bias at shadow edges and
// contacts, 16 anti-aliasing positions per pixel at silhouettes, tessellated
// spheres. They are not loosened to pass.
#include <cmath>
#include <filesystem>
#include <unistd.h>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <safegi/runtime_gl/context.hpp>

#include "safegi/cpu_renderer/image.hpp"
#include "safegi/cpu_renderer/renderer.hpp"
#include "safegi/cpu_renderer/scene_loader.hpp"
#include "safegi/preview/preview.hpp"

namespace safegi::preview {
namespace {

using render::Image;
using render::Scene;

struct Agreement {
  double relative_rmse = 0;      // bench/renderer/image_compare.cpp's: sqrt(mean (v-r)² / (r² + 0.01))
  double mean_ratio[3] = {0, 0, 0};
};

Agreement compare(const Image& image, const Image& reference) {
  Agreement a;
  double sum[3] = {0, 0, 0}, reference_sum[3] = {0, 0, 0}, relative = 0;
  for (size_t i = 0; i < image.rgb.size(); ++i) {
    double v = image.rgb[i], r = reference.rgb[i];
    relative += (v - r) * (v - r) / (r * r + 0.01);
    sum[i % 3] += v;
    reference_sum[i % 3] += r;
  }
  a.relative_rmse = std::sqrt(relative / static_cast<double>(image.rgb.size()));
  for (int c = 0; c < 3; ++c) a.mean_ratio[c] = sum[c] / reference_sum[c];
  return a;
}

Image cpu_direct(Scene scene, int width, int height, int spp) {
  render::RenderOptions options;
  options.settings = scene.settings;
  options.settings.width = width;
  options.settings.height = height;
  options.settings.spp = spp;
  options.settings.integrator = render::IntegratorType::direct;
  options.seed = 7;
  return render::render(scene, options);
}

// One comparison: the scene, the image size, the CPU renderer's samples per
// pixel, the preview's sampling, and the relative-RMSE tolerance (channel
// means must agree within 1 % in every case).
struct Case {
  std::string scene_file;
  int width, height, cpu_spp;
  int light_samples, passes;
  double max_relative_rmse;
};

class CrossValidation : public ::testing::Test {
 protected:
  gl::Context context;

  Agreement check(const Scene& scene, int width, int height, int spp, PreviewOptions options) {
    options.width = width;
    options.height = height;
    Preview preview(scene, options);
    Image gl_image = preview.render();
    Image cpu_image = cpu_direct(scene, width, height, spp);
    for (float v : gl_image.rgb) EXPECT_TRUE(std::isfinite(v));
    Agreement a = compare(gl_image, cpu_image);
    std::printf("relative RMSE %.4f, mean ratio %.4f %.4f %.4f\n", a.relative_rmse, a.mean_ratio[0], a.mean_ratio[1],
                a.mean_ratio[2]);
    return a;
  }

  void expect_agreement(const Case& c) {
    PreviewOptions options;
    options.light_samples = c.light_samples;
    options.passes = c.passes;
    Agreement a = check(render::load_scene(c.scene_file), c.width, c.height, c.cpu_spp, options);
    EXPECT_LT(a.relative_rmse, c.max_relative_rmse);
    for (double ratio : a.mean_ratio) EXPECT_NEAR(ratio, 1.0, 0.01);
  }
};

std::string bundled(const char* file) { return std::string(SAFEGI_SCENES_DIR) + "/" + file; }

// The Cornell box lit by its area light: 1024 light samples per pixel (64 × 16 passes).
TEST_F(CrossValidation, CornellBoxAreaLight) {
  expect_agreement({bundled("cornell-box/cornell-box.json"), 64, 64, 1024, 64, 16, 0.04});
}

// The box lit by a point light instead: hard shadows from the cube map.
TEST_F(CrossValidation, CornellBoxPointLight) {
  expect_agreement({SAFEGI_PREVIEW_SCENES_DIR "/cornell-point-light.json", 64, 64, 256, 16, 16, 0.02});
}

// Phong spheres under a point light and an area light.
TEST_F(CrossValidation, PhongPointAndAreaLight) {
  expect_agreement({bundled("phong.json"), 100, 40, 1024, 64, 16, 0.045});
}

// Motion blur: 32 shutter times accumulated against the CPU renderer's random times.
TEST_F(CrossValidation, MotionBlur) {
  expect_agreement({bundled("motion-blur.json"), 80, 60, 1024, 32, 32, 0.025});
}

// A moving emitter: each shutter time samples the sphere where it is then.
// Sampled at its shutter-open pose instead, the image measured relative RMSE
// 0.40 and means 8 % low. What is left (0.087) is mostly the sphere's own
// streak, drawn at 128 discrete times against the CPU's random ones.
TEST_F(CrossValidation, MovingEmitter) {
  expect_agreement({bundled("moving-light.json"), 80, 60, 1024, 8, 128, 0.17});
}

// A planar mirror (one bounce: the scene rendered through its plane) and a
// spot light, against the CPU renderer's direct lighting, which follows
// mirrors. No mirror sees another here, so one bounce is the whole answer.
TEST_F(CrossValidation, PlanarMirrorAndSpotLight) {
  expect_agreement({SAFEGI_PREVIEW_SCENES_DIR "/mirror-planes.json", 96, 72, 1024, 8, 64, 0.03});
}

// Curved mirrors are not reflected: the preview names them (main() says so
// on stderr and in the image files) and composites only the planar ones.
TEST_F(CrossValidation, CurvedMirrorsAreNamedPlanarOnesReflect) {
  Scene scene = render::load_scene(bundled("mirror.json"));
  PreviewOptions options;
  options.width = 32;
  options.height = 32;
  options.passes = 3;
  options.light_samples = 2;
  Preview preview(scene, options);
  EXPECT_EQ(preview.curved_mirrors(), std::vector<std::string>{"mirror ball"});
  FrameStats stats;
  preview.render(&stats);
  EXPECT_EQ(stats.mirror_views, 3);  // the mirror wall, once per pass
}

// What the preview does not model is named, shape by shape, for main() to
// say on stderr and in the image files; the plastic ball is drawn (its
// diffuse layer), the glass ball is not, a translucent sheet by its diffuse reflection.
TEST_F(CrossValidation, ApproximationsAreNamed) {
  Scene scene = render::load_scene(bundled("environment.json"));
  PreviewOptions options;
  options.width = 16;
  options.height = 16;
  options.passes = 1;
  Preview preview(scene, options);
  EXPECT_EQ(preview.approximations(),
            (std::vector<std::string>{"glass is not previewed and appears black (glass ball)",
                                      "plastic is drawn as its diffuse layer, without its coating's reflection (plastic ball)",
                                      "the environment light is not previewed (no light from it)"}));
  const std::filesystem::path directory =
      std::filesystem::temp_directory_path() / ("safegi-preview-texture-" + std::to_string(::getpid()));
  std::filesystem::create_directories(directory);
  render::Image grey{2, 2, std::vector<float>(12, 0.5f)};
  render::write_pfm(directory / "grey.pfm", grey);
  Scene textured = render::parse_scene(R"({"camera": {"position": ["0 m", "1 m", "3 m"], "look_at": ["0 m", "0 m", "0 m"],
      "up": [0, 1, 0], "fov": "40 deg"},
    "textures": {"grey": {"type": "image", "file": "grey.pfm"}},
    "materials": {"floor": {"type": "lambert", "reflectance": {"texture": "grey"}}},
    "shapes": [{"name": "floor", "type": "quad", "material": "floor", "origin": ["-1 m", "0 m", "-1 m"],
                "edge_u": ["0 m", "0 m", "2 m"], "edge_v": ["2 m", "0 m", "0 m"]}],
    "lights": [{"type": "point", "position": ["0 m", "2 m", "0 m"], "power": "10 W"}]})",
                                       "textured.json", directory);
  std::filesystem::remove_all(directory);
  EXPECT_EQ(Preview(textured, options).approximations(),
            std::vector<std::string>{"textures are drawn as their mean colour (floor)"});
  EXPECT_TRUE(Preview(render::load_scene(bundled("cornell-box/cornell-box.json")), options).approximations().empty());
  Scene translucent = render::parse_scene(R"({"camera": {"position": ["0 m", "1 m", "3 m"], "look_at": ["0 m", "0 m", "0 m"],
      "up": [0, 1, 0], "fov": "40 deg"},
    "materials": {"paper": {"type": "translucent", "diffuse": 0.8, "specular": 0.1, "reflect": 0.4, "transmit": 0.6,
                            "alpha": 0.2}},
    "shapes": [{"name": "sheet", "type": "quad", "material": "paper", "origin": ["-1 m", "0 m", "-1 m"],
                "edge_u": ["0 m", "0 m", "2 m"], "edge_v": ["2 m", "0 m", "0 m"]}],
    "lights": [{"type": "point", "position": ["0 m", "2 m", "0 m"], "power": "10 W"}]})",
                                          "translucent.json", ".");
  EXPECT_EQ(Preview(translucent, options).approximations(),
            std::vector<std::string>{"translucent is drawn as its diffuse reflection (reflect times Kd), without its "
                                     "glossy lobes or the light it lets through (sheet)"});
  Scene clay = render::parse_scene(R"({"camera": {"position": ["0 m", "1 m", "3 m"], "look_at": ["0 m", "0 m", "0 m"],
      "up": [0, 1, 0], "fov": "40 deg"},
    "materials": {"clay": {"type": "oren_nayar", "reflectance": 0.6, "sigma": "20 deg"}},
    "shapes": [{"name": "pot", "type": "sphere", "material": "clay", "center": ["0 m", "0 m", "0 m"], "radius": "1 m"}],
    "lights": [{"type": "point", "position": ["0 m", "2 m", "2 m"], "power": "10 W"}]})",
                                   "clay.json", ".");
  EXPECT_EQ(Preview(clay, options).approximations(),
            std::vector<std::string>{"rough diffuse (Oren-Nayar) surfaces are drawn as Lambertian (pot)"});
  Scene projector = render::parse_scene(R"({"camera": {"position": ["0 m", "1 m", "3 m"], "look_at": ["0 m", "0 m", "0 m"],
      "up": [0, 1, 0], "fov": "40 deg"},
    "shapes": [{"type": "sphere", "center": ["0 m", "0 m", "0 m"], "radius": "1 m"}],
    "lights": [{"type": "point", "position": ["0 m", "2 m", "2 m"], "power": "10 W",
                "map": {"layout": "projection", "fov": "30 deg"}}]})",
                                        "projector.json", ".");
  EXPECT_EQ(Preview(projector, options).approximations(),
            std::vector<std::string>{"goniometric and projection lights are drawn as point lights of their mean "
                                     "intensity, without their map (point_lights[0])"});
}

// The rasteriser draws through a pinhole: another camera is refused with the
// renderer that draws it, not drawn as a perspective one.
TEST_F(CrossValidation, RefusesCamerasItCannotDraw) {
  Scene scene = render::load_scene(bundled("cornell-box/cornell-box.json"));
  scene.camera.projection = render::CameraProjection::orthographic;
  scene.camera.view_size = safegi::from_raw<decltype(scene.camera.view_size)>(1.0f);
  try {
    Preview preview(scene, PreviewOptions{});
    ADD_FAILURE() << "an orthographic camera was previewed";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(),
                 "the preview draws perspective cameras only, and this scene's is orthographic: render it with "
                 "safegi-render");
  }
}

}  // namespace
}  // namespace safegi::preview
