// Participating media against analytic answers: Beer–Lambert through an
// absorbing fog, single scattering of sunlight (an integral along the view
// ray, evaluated here independently), and a white furnace (a scattering fog
// that absorbs nothing, inside a uniform sky, is exactly the sky's radiance).
// The scenes are pbrt-v3 files, as the media come from them; the camera sits
// at the centre of an invisible fog sphere, so that every view ray crosses R
// of fog and then the boundary.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "render_test_support.hpp"
#include "safegi/cpu_renderer/pbrt_import.hpp"

namespace safegi::render {
namespace {

using namespace test_support;

constexpr double kRadius = 1.0;  // of the fog sphere around the camera, metres

struct Fog {
  double absorption[3];
  double scattering[3];
  double asymmetry;
};

std::string rgb(const double (&c)[3]) {
  return "[" + std::to_string(c[0]) + " " + std::to_string(c[1]) + " " + std::to_string(c[2]) + "]";
}

// The camera at the origin looking along `view`, inside a fog sphere of
// kRadius (material "": no surface), with `lights` in the world block.
Scene fog_scene(const Fog& fog, const std::string& view, const std::string& lights, int max_depth) {
  const std::string text =
      "LookAt 0 0 0 " + view + " 0 0 1\nCamera \"perspective\" \"float fov\" 0.5\n"
      "Film \"image\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
      "Integrator \"volpath\" \"integer maxdepth\" " + std::to_string(max_depth) + "\n" +
      "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\" \"rgb sigma_a\" " + rgb(fog.absorption) +
      " \"rgb sigma_s\" " + rgb(fog.scattering) + " \"float g\" " + std::to_string(fog.asymmetry) + "\n" +
      "WorldBegin\n" + lights + "\nAttributeBegin\nMediumInterface \"fog\" \"\"\nMaterial \"\"\n" +
      "Shape \"sphere\" \"float radius\" " + std::to_string(kRadius) + "\nAttributeEnd\n" +
      "MediumInterface \"\" \"fog\"\nWorldEnd\n";  // the camera's medium: the outside one at WorldEnd
  PbrtImportOptions options;
  options.metres_per_unit = 1;
  PbrtScene scene = parse_pbrt_scene(text, "fog.pbrt", ".", options);
  EXPECT_EQ(scene.scene.camera.medium, 0);
  return std::move(scene.scene);
}

// Each channel's image mean within four standard errors (and `relative`) of `expected`.
void expect_channels(const Image& image, const double (&expected)[3], double relative, const std::string& what) {
  for (int c = 0; c < 3; ++c) {
    Estimate estimate = channel_estimate(image, c);
    EXPECT_NEAR(estimate.mean, expected[c], 4 * estimate.standard_error + relative * expected[c])
        << what << ", channel " << c << " (standard error " << estimate.standard_error << ")";
  }
}

// Behind the fog, a black sphere emitting Le (pbrt-v3's area light) fills the
// view: what arrives is Le·exp(−σa R) per channel, and scattering adds
// nothing (σs = 0), whatever the estimator knobs.
TEST(RenderMedia, AbsorbingFogIsBeerLambert) {
  const Fog fog{{0.5, 1.0, 2.0}, {0, 0, 0}, 0};
  const double radiance = 3.0;
  const std::string emitter = "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [3 3 3] \"bool twosided\" \"true\"\n"
                              "Material \"matte\" \"rgb Kd\" [0 0 0]\nShape \"sphere\" \"float radius\" 4\nAttributeEnd";
  Scene scene = fog_scene(fog, "1 0 0", emitter, 5);
  double expected[3];
  for (int c = 0; c < 3; ++c) expected[c] = radiance * std::exp(-fog.absorption[c] * kRadius);
  for (const Knobs& knobs : estimator_knobs()) expect_channels(render_scene(scene, 256, 2, std::nullopt, knobs.apply), expected, 1e-3, knobs.name);
}

// Single scattering (maxdepth 1: one scattering event) of a sun of
// irradiance E along ω: looking along v, L = E σs p(v·ω) ∫₀ᴿ e^(−σt (t + s(t))) dt,
// s(t) the way out of the sphere from t·v towards the sun, p Henyey–Greenstein's.
TEST(RenderMedia, SingleScatteringOfSunlight) {
  const double irradiance = 2.0;
  for (double g : {0.0, 0.6, -0.4}) {
    const Fog fog{{0.1, 0.2, 0.3}, {0.5, 1.0, 1.5}, g};
    // The sun 60° from the view: v = x, ω = (cos 60°, sin 60°, 0).
    const double cos_angle = 0.5, sin_angle = std::sqrt(0.75);
    const std::string sun = "LightSource \"distant\" \"point from\" [" + std::to_string(cos_angle) + " " +
                            std::to_string(sin_angle) + " 0] \"point to\" [0 0 0] \"rgb L\" [2 2 2]";
    Scene scene = fog_scene(fog, "1 0 0", sun, 1);
    // Light travels along −ω and leaves along −v: the angle between them is the view's to the sun.
    const double phase = (1 - g * g) / (4 * kPiD * std::pow(1 + g * g - 2 * g * cos_angle, 1.5));
    double expected[3];
    for (int c = 0; c < 3; ++c) {
      const double extinction = fog.absorption[c] + fog.scattering[c];
      const int steps = 2000;
      double integral = 0;  // Simpson's rule
      for (int i = 0; i <= steps; ++i) {
        const double t = kRadius * i / steps;
        const double out = -t * cos_angle + std::sqrt(kRadius * kRadius - t * t * sin_angle * sin_angle);
        const double weight = i == 0 || i == steps ? 1 : (i % 2 ? 4 : 2);
        integral += weight * std::exp(-extinction * (t + out));
      }
      integral *= kRadius / steps / 3;
      expected[c] = irradiance * fog.scattering[c] * phase * integral;
    }
    for (const Knobs& knobs : estimator_knobs())
      expect_channels(render_scene(scene, 1024, 2, std::nullopt, knobs.apply), expected, 2e-3,
                      "g " + std::to_string(g) + ", " + knobs.name);
  }
}

// A white furnace: fog that scatters (forwards, backwards or evenly) and
// absorbs nothing, lit by a uniform sky of radiance L from every direction,
// is L everywhere, however many times light scatters in it.
TEST(RenderMedia, ScatteringFogInAUniformSkyIsAWhiteFurnace) {
  for (double g : {0.0, 0.8, -0.5}) {
    const Fog fog{{0, 0, 0}, {1.0, 1.5, 2.0}, g};
    Scene scene = fog_scene(fog, "0 1 0", "LightSource \"infinite\" \"rgb L\" [0.7 0.7 0.7]", 1000);
    const double expected[3] = {0.7, 0.7, 0.7};
    for (const Knobs& knobs : estimator_knobs())
      expect_channels(render_scene(scene, 1024, 2, std::nullopt, knobs.apply), expected, 1e-3,
                      "g " + std::to_string(g) + ", " + knobs.name);
  }
}

// The photon map is traced as if in vacuum: a scene with media is refused,
// not rendered without them.
TEST(RenderMedia, PhotonMappingRefusesMedia) {
  Scene scene = fog_scene({{0, 0, 0}, {1, 1, 1}, 0}, "1 0 0", "LightSource \"infinite\"", 5);
  scene.settings.integrator = IntegratorType::photon;
  RenderOptions options;
  options.settings = scene.settings;
  try {
    render(scene, options);
    ADD_FAILURE() << "rendered";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(),
                 "the photon integrator does not trace participating media or invisible surfaces: render with \"path\"");
  }
}

}  // namespace
}  // namespace safegi::render
