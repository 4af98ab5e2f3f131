// Numerical stability at the extremes (issue 8): scene scale, radiance range,
// grazing light, thin and huge triangles, camera inside geometry, zero-area
// lights, degenerate transforms. Tiny images, few samples; tolerances from the
// estimator's variance or from float rounding where the estimator is exact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <numbers>
#include <string>

#include "safegi/cpu_renderer/precision.hpp"
#include "safegi/cpu_renderer/renderer.hpp"
#include "safegi/cpu_renderer/scene_loader.hpp"

namespace safegi::render {
namespace {

Image render_text(const std::string& json, int spp) {
  Scene scene = parse_scene(json, "extreme.json", ".");
  RenderOptions options;
  options.settings = scene.settings;
  options.settings.spp = spp;
  options.threads = 2;
  RenderStats stats;
  Image image = render(scene, options, &stats);
  EXPECT_EQ(stats.invalid_samples, 0u);
  for (float v : image.rgb) EXPECT_TRUE(std::isfinite(v) && v >= 0) << v;
  return image;
}

std::string number(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

std::string metres(double x, double y, double z) {
  return R"({"value": [)" + number(x) + ", " + number(y) + ", " + number(z) + R"(], "unit": "m"})";
}

std::string quad(double scale, const double o[3], const double u[3], const double v[3], const std::string& extra) {
  return R"({"type": "quad", "origin": )" + metres(scale * o[0], scale * o[1], scale * o[2]) +
         R"(, "edge_u": )" + metres(scale * u[0], scale * u[1], scale * u[2]) + R"(, "edge_v": )" +
         metres(scale * v[0], scale * v[1], scale * v[2]) + (extra.empty() ? "" : ", " + extra) + "}";
}

// An open box (floor, back and left walls) under a downward ceiling light,
// every length multiplied by `scale` metres.
std::string open_box(double scale, double radiance, const std::string& integrator = "path") {
  const double floor_o[3] = {-1, 0, -1}, floor_u[3] = {0, 0, 2}, floor_v[3] = {2, 0, 0};
  const double back_o[3] = {-1, 0, -1}, back_u[3] = {2, 0, 0}, back_v[3] = {0, 2, 0};
  const double left_o[3] = {-1, 0, -1}, left_u[3] = {0, 2, 0}, left_v[3] = {0, 0, 2};
  const double light_o[3] = {-0.25, 1.9, -0.25}, light_u[3] = {0.5, 0, 0}, light_v[3] = {0, 0, 0.5};
  return R"({"render": {"resolution": [16, 16], "integrator": ")" + integrator + R"(", "max_depth": 5},
    "camera": {"position": )" + metres(0, scale, 3.5 * scale) + R"(, "look_at": )" + metres(0, scale, 0) +
         R"(, "up": [0, 1, 0], "fov": "40 deg"},
    "materials": {"white": {"type": "lambert", "reflectance": 0.7}, "red": {"type": "lambert", "reflectance": [0.6, 0.1, 0.1]}},
    "shapes": [)" + quad(scale, floor_o, floor_u, floor_v, R"("material": "white")") + ", " +
         quad(scale, back_o, back_u, back_v, R"("material": "white")") + ", " +
         quad(scale, left_o, left_u, left_v, R"("material": "red")") + ", " +
         quad(scale, light_o, light_u, light_v, R"("emission": ")" + number(radiance) + " W/m2/sr\"") + "]}";
}

// Mean over all pixels and channels, and the standard error of that mean
// estimated from the per-pixel differences of two images (pixels independent).
struct Difference {
  double mean_a, mean_difference, standard_error;
};
Difference compare(const Image& a, const Image& b) {
  double sum_a = 0, sum_d = 0, sum_d2 = 0;
  size_t n = a.rgb.size();
  for (size_t i = 0; i < n; ++i) {
    double d = double(b.rgb[i]) - a.rgb[i];
    sum_a += a.rgb[i];
    sum_d += d;
    sum_d2 += d * d;
  }
  double mean_d = sum_d / n;
  double variance = std::max(0.0, sum_d2 / n - mean_d * mean_d) * n / (n - 1);
  return {sum_a / n, mean_d, std::sqrt(variance / n)};
}

double max_value(const Image& image) { return *std::max_element(image.rgb.begin(), image.rgb.end()); }

// --- Scene scale ----------------------------------------------------------

TEST(Extremes, SceneScaleFromTenthMillimetreTo100KilometresRendersTheSameImage) {
  Image reference = render_text(open_box(1, 5), 16);
  for (double scale : {1e-4, 1e5}) {
    Image image = render_text(open_box(scale, 5), 16);
    Difference d = compare(reference, image);
    // Same sample sequences: the images differ only where float rounding moves
    // a hit; the mean difference must stay within 4 standard errors of its
    // own noise, and that noise must be small (the test has power).
    EXPECT_LT(std::fabs(d.mean_difference), 4 * d.standard_error + 1e-5 * d.mean_a) << scale;
    EXPECT_LT(d.standard_error, 0.01 * d.mean_a) << scale;
    std::printf("scale %g m: mean %.5g difference %.3g se %.3g\n", scale, d.mean_a, d.mean_difference, d.standard_error);
  }
}


// --- Radiance range ---------------------------------------------------------

TEST(Extremes, RadianceFrom1eMinus30To1e36ScalesLinearly) {
  for (const char* integrator : {"direct", "path"}) {
    Image reference = render_text(open_box(1, 1, integrator), 8);
    for (double radiance : {1e-10, 1e10, 1e-30, 1e30, 1e36}) {
      Image image = render_text(open_box(1, radiance, integrator), 8);
      double worst = 0;
      for (size_t i = 0; i < image.rgb.size(); ++i) {
        if (reference.rgb[i] == 0) {
          EXPECT_EQ(image.rgb[i], 0.0f);
          continue;
        }
        EXPECT_GT(image.rgb[i], 0.0f) << "underflow at " << i;
        worst = std::max(worst, std::fabs(image.rgb[i] / (radiance * reference.rgb[i]) - 1));
      }
      // The estimator is linear in the emission and uses the same samples: only
      // float rounding of the products along a path (a few dozen operations).
      EXPECT_LT(worst, 1e-5) << integrator << " " << radiance;
      std::printf("radiance %s %g: worst relative %.3g\n", integrator, radiance, worst);
    }
  }
}

// --- Grazing light ------------------------------------------------------------

// A point light at height h above a lambertian plane, seen from straight
// above: L = ρ/π · I · h / r³, with cos θ = h / r down to ~1e-6.
TEST(Extremes, PointLightGrazingThePlane) {
  const double rho = 0.5, intensity = 10.0, camera_height = 5.0;
  for (double height : {1e-3, 1e-6}) {
    std::string text = R"({"render": {"resolution": [17, 17], "integrator": "direct"},
      "camera": {"position": {"value": [0, 5, 0], "unit": "m"}, "look_at": {"value": [0, 0, 0], "unit": "m"},
                 "up": [0, 0, -1], "fov": "40 deg"},
      "materials": {"matte": {"type": "lambert", "reflectance": 0.5}},
      "shapes": [{"type": "quad", "material": "matte", "origin": {"value": [-10, 0, -10], "unit": "m"},
                  "edge_u": {"value": [0, 0, 20], "unit": "m"}, "edge_v": {"value": [20, 0, 0], "unit": "m"}}],
      "lights": [{"type": "point", "position": )" + metres(0, height, 0) + R"(, "intensity": "10 W/sr"}]})";
    Image image = render_text(text, 16);
    const double half = std::tan(20.0 * std::numbers::pi / 180);
    double worst = 0;
    for (int py = 0; py < 17; ++py)
      for (int px = 0; px < 17; ++px) {
        if (std::abs(px - 8) <= 1 && std::abs(py - 8) <= 1) continue;  // around the light's foot cos θ / r³ varies too fast within a pixel for 16 samples
        double expected = 0;
        constexpr int kSub = 16;
        for (int j = 0; j < kSub; ++j)
          for (int i = 0; i < kSub; ++i) {
            double x = camera_height * (2 * (px + (i + 0.5) / kSub) / 17 - 1) * half;
            double z = -camera_height * (1 - 2 * (py + (j + 0.5) / kSub) / 17) * half;
            double r = std::sqrt(x * x + z * z + height * height);
            expected += rho / std::numbers::pi * intensity * height / (r * r * r);
          }
        expected /= kSub * kSub;
        worst = std::max(worst, std::fabs(image.pixel(px, py)[0] / expected - 1));
      }
    // 16 stratified positions per pixel of a smooth function; the closed form
    // itself is averaged on a 16x16 grid: a few percent at most near the centre.
    EXPECT_LT(worst, 0.05) << height;
    std::printf("grazing point light h=%g: worst relative %.3g\n", height, worst);
  }
}

// An emitter facing up a hair above the floor: the floor next to it sees the
// light at grazing angles on both ends. No pixel may exceed the emitter's own
// radiance (with MIS each sample of a lambertian floor is at most 1.5 ρ Le).
TEST(Extremes, EmitterNearlyCoplanarWithTheFloor) {
  const double le = 4;
  for (double gap : {1e-3, 1e-5, 1e-7}) {
    for (const char* integrator : {"direct", "path"}) {
      const double floor_o[3] = {-10, 0, -10}, floor_u[3] = {0, 0, 20}, floor_v[3] = {20, 0, 0};
      const double light_o[3] = {-0.5, gap, -0.5}, light_u[3] = {0, 0, 1}, light_v[3] = {1, 0, 0};
      std::string text = std::string(R"({"render": {"resolution": [16, 16], "integrator": ")") + integrator +
                         R"(", "max_depth": 4},
        "camera": {"position": {"value": [0, 0.3, 2], "unit": "m"}, "look_at": {"value": [0, 0, 0], "unit": "m"},
                   "up": [0, 1, 0], "fov": "60 deg"},
        "materials": {"matte": {"type": "lambert", "reflectance": 0.9}},
        "shapes": [)" + quad(1, floor_o, floor_u, floor_v, R"("material": "matte")") + ", " +
                         quad(1, light_o, light_u, light_v, R"("emission": "4 W/m2/sr")") + "]}";
      Image image = render_text(text, 16);
      EXPECT_LE(max_value(image), le * (1 + 1e-6)) << gap << " " << integrator;
      std::printf("coplanar emitter gap=%g %s: max %.4g mean %.4g\n", gap, integrator, max_value(image),
                  compare(image, image).mean_a);
    }
  }
}

// --- Thin and huge triangles ---------------------------------------------------

std::string floor_scene(const std::string& floor_shape) {
  return R"({"render": {"resolution": [16, 16], "integrator": "path", "max_depth": 3},
    "camera": {"position": {"value": [0, 3, 3], "unit": "m"}, "look_at": {"value": [0, 0, 0], "unit": "m"},
               "up": [0, 1, 0], "fov": "40 deg"},
    "materials": {"matte": {"type": "lambert", "reflectance": 0.6}},
    "shapes": [)" + floor_shape + R"(,
      {"type": "quad", "origin": {"value": [-0.5, 1, -0.5], "unit": "m"}, "edge_u": {"value": [1, 0, 0], "unit": "m"},
       "edge_v": {"value": [0, 0, 1], "unit": "m"}, "emission": "10 W/m2/sr"}]})";
}

// The floor [-2, 2]² cut along x into strips as thin as 1e-6 m (triangles of
// aspect ratio 4e6) renders as one quad: no cracks along the shared edges.
TEST(Extremes, SliverTrianglesRenderLikeOneQuad) {
  const double o[3] = {-2, 0, -2}, u[3] = {0, 0, 4}, v[3] = {4, 0, 0};
  Image reference = render_text(floor_scene(quad(1, o, u, v, R"("material": "matte")")), 16);
  const double cuts[] = {-2, -1e-3, -1e-6, 0, 1e-6, 1e-3, 2};
  std::string positions, indices;
  for (double x : cuts) positions += (positions.empty() ? "" : ", ") + ("[" + number(x) + ", 0, -2], [" + number(x) + ", 0, 2]");
  for (int i = 0; i + 1 < int(std::size(cuts)); ++i) {
    // (x_i, -2), (x_i, 2), (x_i+1, 2), (x_i+1, -2): normal up is (x_i,-2) → (x_i,2) → (x_i+1,2)
    int a = 2 * i, b = 2 * i + 1, c = 2 * i + 3, d = 2 * i + 2;
    indices += (indices.empty() ? "" : ", ") + std::to_string(a) + ", " + std::to_string(b) + ", " + std::to_string(c) +
               ", " + std::to_string(a) + ", " + std::to_string(c) + ", " + std::to_string(d);
  }
  std::string slivers = R"({"type": "triangles", "material": "matte", "positions": {"unit": "m", "value": [)" +
                        positions + R"(]}, "indices": [)" + indices + "]}";
  Image image = render_text(floor_scene(slivers), 16);
  Difference d = compare(reference, image);
  EXPECT_LT(std::fabs(d.mean_difference), 4 * d.standard_error + 1e-5 * d.mean_a);
  EXPECT_LT(d.standard_error, 0.01 * d.mean_a);
  std::printf("slivers: mean %.5g difference %.3g se %.3g\n", d.mean_a, d.mean_difference, d.standard_error);
}

// A floor 2e7 m wide (float spacing ~1 m at its corners) lit 1 m above its centre
// renders as a 40 m floor (which already fills the view): hit points and ray
// offsets must not scale with the triangle's far-away vertices. Level and tilted
// by 10 deg (then no coordinate of the plane is exact).
TEST(Extremes, HugeTriangleRendersLikeASmallOne) {
  for (double tilt : {0.0, 10.0}) {
    const double c = std::cos(tilt * std::numbers::pi / 180), s = std::sin(tilt * std::numbers::pi / 180);
    const double o[3] = {-2 * c, 2 * s, -2}, u[3] = {0, 0, 4}, v[3] = {4 * c, -4 * s, 0};
    Image reference = render_text(floor_scene(quad(10, o, u, v, R"("material": "matte")")), 16);
    Image image = render_text(floor_scene(quad(5e6, o, u, v, R"("material": "matte")")), 16);
    Difference d = compare(reference, image);
    EXPECT_LT(std::fabs(d.mean_difference), 4 * d.standard_error + 1e-5 * d.mean_a) << tilt;
    EXPECT_LT(d.standard_error, 0.01 * d.mean_a) << tilt;
    std::printf("huge, tilt %g: mean %.5g difference %.3g se %.3g\n", tilt, d.mean_a, d.mean_difference, d.standard_error);
  }
}

// --- Camera inside geometry ------------------------------------------------------

TEST(Extremes, CameraInsideAClosedSphereSeesOnlyDarkness) {
  std::string text = R"({"render": {"resolution": [8, 8], "integrator": "path", "max_depth": 8},
    "camera": {"position": {"value": [0, 0, 0], "unit": "m"}, "look_at": {"value": [0, 0, -1], "unit": "m"},
               "up": [0, 1, 0], "fov": "90 deg"},
    "materials": {"matte": {"type": "lambert", "reflectance": 0.8}},
    "shapes": [{"type": "sphere", "material": "matte", "center": {"value": [0, 0, 0], "unit": "m"}, "radius": "1 mm"},
               {"type": "sphere", "center": {"value": [0, 5, 0], "unit": "m"}, "radius": "1 m", "emission": "100 W/m2/sr"}],
    "lights": [{"type": "point", "position": {"value": [0, 0, 3], "unit": "m"}, "power": "1000 W"}]})";
  Image image = render_text(text, 16);
  EXPECT_EQ(max_value(image), 0.0f);
}

// --- Far from the origin ----------------------------------------------------

// Decision: a shape float cannot resolve where it stands is reported, never
// rendered silently wrong (bench/precision_scale: the Cornell box 1e7 m from
// the origin renders black in float). Spheres of radius 0.5 m at distance D
// along x; a 2e5 m floor at the origin is resolved (its own size is large).
Scene far_spheres(double distance) {
  return parse_scene(R"({"camera": {"position": )" + metres(distance, 0, 5) + R"(, "look_at": )" +
                         metres(distance, 0, 0) + R"(, "up": [0, 1, 0], "fov": "40 deg"},
    "shapes": [{"type": "quad", "name": "floor", "origin": )" + metres(-1e5, -1, -1e5) + R"(, "edge_u": )" +
                         metres(2e5, 0, 0) + R"(, "edge_v": )" + metres(0, 0, 2e5) + R"(},
               {"type": "sphere", "name": "ball", "center": )" + metres(distance, 0, 0) + R"(, "radius": "0.5 m"},
               {"type": "sphere", "center": )" + metres(-distance, 0, 0) + R"(, "radius": "0.5 m"}]})",
                     "far.json", ".");
}

TEST(Extremes, ShapesFloatCannotResolveWhereTheyStandAreReported) {
  EXPECT_FALSE(check_precision(far_spheres(1e3)));
  EXPECT_FALSE(check_precision(far_spheres(1e4)));  // spacing 0.001 m: 0.06 % of the ball (1.73 m across)
  Scene point_like;  // a triangle collapsed to a point: nothing to resolve, wherever it is
  point_like.shapes.emplace_back();
  point_like.shapes[0].positions.assign(3, sg::from_raw<PointObject>(sg::vec3_rep(1, 2, 3)));
  point_like.shapes[0].indices = {0, 1, 2};
  EXPECT_FALSE(check_precision(point_like));
  std::optional<PrecisionReport> far = check_precision(far_spheres(1e7));
  ASSERT_TRUE(far);
  EXPECT_EQ(far->unresolved_shapes, 2);
  EXPECT_EQ(far->worst_shape, 1);  // the first of the two equally bad balls
  EXPECT_NEAR(far->worst_size_m, std::sqrt(3.0), 1e-6);
  EXPECT_DOUBLE_EQ(far->worst_distance_m, 1e7 + 0.5);
  if (sizeof(Real) == sizeof(float)) {
    EXPECT_DOUBLE_EQ(far->worst_spacing_m, 1.0);  // floats in [2^23, 2^24) are 1 apart
    EXPECT_EQ(describe(*far, far_spheres(1e7)),
              "warning: 2 shapes are too small for float where they stand: shapes[1] \"ball\" is 1.73 m across and "
              "1e+07 m from the origin, where float values are 1 m apart (57.7 % of its size); expect a wrong image\n"
              "help: render it in double (safegi-render-double), or move the scene towards the origin\n");
  }
}

// --- Zero-area lights ------------------------------------------------------------

// Decision: an emitter whose area is 0 in float (collinear or tiny triangles)
// contributes exactly nothing; the image equals the scene without it. A quad
// with parallel edges is a scene error instead (it is always a typo).
TEST(Extremes, ZeroAndTinyAreaEmittersContributeExactlyNothing) {
  auto scene = [](const std::string& emitter) {
    return R"({"render": {"resolution": [8, 8], "integrator": "path", "max_depth": 3},
      "camera": {"position": {"value": [0, 3, 3], "unit": "m"}, "look_at": {"value": [0, 0, 0], "unit": "m"},
                 "up": [0, 1, 0], "fov": "40 deg"},
      "materials": {"matte": {"type": "lambert", "reflectance": 0.6}},
      "shapes": [{"type": "quad", "material": "matte", "origin": {"value": [-2, 0, -2], "unit": "m"},
                  "edge_u": {"value": [0, 0, 4], "unit": "m"}, "edge_v": {"value": [4, 0, 0], "unit": "m"}})" +
           emitter + R"(],
      "lights": [{"type": "point", "position": {"value": [0, 2, 0], "unit": "m"}, "power": "100 W"}]})";
  };
  Image reference = render_text(scene(""), 8);
  for (double edge : {0.0, 1e-25, 1e-22, 1e-20, 1e-19}) {
    std::string emitter = R"(, {"type": "triangles", "emission": "1e6 W/m2/sr", "positions": {"unit": "m", "value":
        [[0, 1, 0], [)" + number(edge) + R"(, 1, 0], [0, 1, )" + number(edge) + R"(]]}, "indices": [0, 2, 1]})";
    Image image = render_text(scene(emitter), 8);
    EXPECT_EQ(image.rgb, reference.rgb) << edge;
  }
  EXPECT_THROW(
      {
        try {
          parse_scene(R"({"camera": {"position": ["0 m", "0 m", "1 m"], "look_at": ["0 m", "0 m", "0 m"], "up": [0, 1, 0], "fov": "40 deg"},
            "shapes": [{"type": "quad", "origin": ["0 m", "0 m", "0 m"], "edge_u": ["1 m", "0 m", "0 m"],
                        "edge_v": ["2 m", "0 m", "0 m"], "emission": "1 W/m2/sr"}]})",
                      "zero.json", ".");
        } catch (const SceneError& error) {
          EXPECT_STREQ(error.what(), "zero.json: shapes[0]: edge_u and edge_v must span a parallelogram");
          throw;
        }
      },
      SceneError);
}

// --- Invalid input at the float limits ---------------------------------------------

std::string scene_error(const std::string& shape_fields, const std::string& emission = "1 W/m2/sr") {
  std::string text = R"({"camera": {"position": ["0 m", "0 m", "1 m"], "look_at": ["0 m", "0 m", "0 m"], "up": [0, 1, 0], "fov": "40 deg"},
    "shapes": [{"type": "sphere", "center": ["0 m", "0 m", "0 m"], "radius": "1 m", "emission": ")" + emission + "\"" +
                     shape_fields + "}]}";
  try {
    parse_scene(text, "limits.json", ".");
  } catch (const SceneError& error) {
    return error.what();
  }
  return "no error";
}

TEST(Extremes, DegenerateTransformsAreSceneErrors) {
  EXPECT_EQ(scene_error(R"(, "transform": [{"scale": 0}])"), "limits.json: shapes[0].transform[0].scale: must not be zero");
  EXPECT_EQ(scene_error(R"(, "transform": [{"scale": 1e-50}])"),
            "limits.json: shapes[0].transform[0].scale: value is out of float range (in SI units its magnitude must be 0 or lie in 1.4e-45 .. 3.4e38)");
  EXPECT_EQ(scene_error(R"(, "transform": [{"scale": 1e-30}, {"scale": 1e-30}])"),
            "limits.json: shapes[0].transform: is singular in float precision (its scales multiply to 0 or infinity)");
  EXPECT_EQ(scene_error(R"(, "transform": [{"scale": 1e20}, {"scale": 1e20}])"),
            "limits.json: shapes[0].transform: is singular in float precision (its scales multiply to 0 or infinity)");
  EXPECT_EQ(scene_error(R"(, "transform": [{"scale": 1e-3}, {"scale": 1e3}])"), "no error");
}

TEST(Extremes, RadianceOutsideTheFloatRangeIsASceneError) {
  EXPECT_EQ(scene_error("", "1e39 W/m2/sr"),
            "limits.json: shapes[0].emission: value is out of float range (in SI units its magnitude must be 0 or lie in 1.4e-45 .. 3.4e38)");
  EXPECT_EQ(scene_error("", "1e-50 W/m2/sr"),
            "limits.json: shapes[0].emission: value is out of float range (in SI units its magnitude must be 0 or lie in 1.4e-45 .. 3.4e38)");
  EXPECT_EQ(scene_error("", "1e-30 W/m2/sr"), "no error");
  EXPECT_EQ(scene_error("", "0 W/m2/sr"), "no error");
}

}  // namespace
}  // namespace safegi::render
