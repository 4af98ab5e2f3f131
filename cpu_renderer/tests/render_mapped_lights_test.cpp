// Goniometric and projection lights over a diffuse plane, against
// L = ρ/π · I m(ω) cos θ / r², where m is the map's texel towards the point,
// interpolated here by an independent bilinear lookup (texel centres at
// half-integers; s wraps and t clamps for goniometric maps, both clamp for
// projection ones), averaged over each pixel's footprint.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <unistd.h>

#include "render_test_support.hpp"
#include "safegi/cpu_renderer/image.hpp"

namespace safegi::render {
namespace {

using namespace test_support;

constexpr int kSize = 33;
constexpr double kRho = 0.5, kIntensity = 10.0, kLightHeight = 2.0, kCameraHeight = 5.0, kFov = 60.0;

// The map: red rises along s, green along t, blue is 1.
Image ramp_map(int width, int height) {
  Image image{width, height, std::vector<float>(3 * static_cast<size_t>(width) * height)};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float* texel = &image.rgb[3 * (static_cast<size_t>(y) * width + x)];
      texel[0] = 0.2f + 0.8f * (x + 0.5f) / width;
      texel[1] = 0.1f + 0.9f * (y + 0.5f) / height;
      texel[2] = 1.0f;
    }
  return image;
}

double bilinear(const Image& map, int channel, double s, double t, bool wrap_s) {
  auto at = [&](int x, int y) {
    x = wrap_s ? ((x % map.width) + map.width) % map.width : std::clamp(x, 0, map.width - 1);
    y = std::clamp(y, 0, map.height - 1);
    return static_cast<double>(map.rgb[3 * (static_cast<size_t>(y) * map.width + x) + channel]);
  };
  const double x = s * map.width - 0.5, y = t * map.height - 0.5;
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const double dx = x - x0, dy = y - y0;
  return (1 - dx) * (1 - dy) * at(x0, y0) + dx * (1 - dy) * at(x0 + 1, y0) + (1 - dx) * dy * at(x0, y0 + 1) +
         dx * dy * at(x0 + 1, y0 + 1);
}

// The plane y = 0 seen from above, lit from (0, 2, 0) by a point light with
// `map_json`; the map is written beside the scene as map.pfm.
Image render_lit_plane(const std::string& map_json, const Image& map, const char* integrator) {
  const std::filesystem::path directory =
      std::filesystem::temp_directory_path() / ("safegi-mapped-light-" + std::to_string(::getpid()));
  std::filesystem::create_directories(directory);
  write_pfm(directory / "map.pfm", map);
  const std::string scene = std::string(R"json({
    "render": {"resolution": [33, 33], "integrator": ")json") + integrator + R"json("},
    "camera": {"position": ["0 m", "5 m", "0 m"], "look_at": ["0 m", "0 m", "0 m"], "up": [0, 0, -1], "fov": "60 deg"},
    "materials": {"matte": {"type": "lambert", "reflectance": 0.5}},
    "shapes": [{"type": "quad", "material": "matte", "origin": ["-10 m", "0 m", "-10 m"],
                "edge_u": ["0 m", "0 m", "20 m"], "edge_v": ["20 m", "0 m", "0 m"]}],
    "lights": [{"type": "point", "position": ["0 m", "2 m", "0 m"], "intensity": "10 W/sr", "map": )json" +
                            map_json + "}]}";
  Image image = render_text(scene, 64, 2, std::nullopt, {}, directory);
  std::filesystem::remove_all(directory);
  return image;
}

// The largest difference from `radiance` (per channel, at a point x, z of the
// plane) relative to the point light's peak, over pixels whose footprint
// `inside` says lies wholly on one side of the map's edges; the others must
// lie between 0 and the peak. Returns how many pixels were compared.
int compare(const Image& image, const std::function<double(double, double, int)>& radiance,
            const std::function<bool(double, double)>& inside, double& worst) {
  const double half = std::tan(kFov / 2 * kPiD / 180), pixel = 2 * kCameraHeight * half / kSize;
  const double peak = kRho / kPiD * kIntensity / (kLightHeight * kLightHeight);
  int compared = 0;
  for (int py = 0; py < kSize; ++py)
    for (int px = 0; px < kSize; ++px) {
      const double cx = kCameraHeight * (2 * (px + 0.5) / kSize - 1) * half;
      const double cz = -kCameraHeight * (1 - 2 * (py + 0.5) / kSize) * half;
      bool whole = true;
      for (double ox : {-pixel, pixel})
        for (double oz : {-pixel, pixel}) whole = whole && inside(cx + ox, cz + oz) == inside(cx, cz);
      for (int c = 0; c < 3; ++c) {
        const double value = image.pixel(px, py)[c];
        if (!whole) {
          EXPECT_GE(value, 0);
          EXPECT_LE(value, peak * (1 + 1e-3));
          continue;
        }
        const double expected = footprint_average(px, py, kSize, half, kCameraHeight,
                                                  [&](double x, double z) { return radiance(x, z, c); });
        worst = std::max(worst, std::fabs(value - expected) / peak);
      }
      compared += whole;
    }
  return compared;
}

double point_light_radiance(double x, double z, double factor) {
  const double r2 = x * x + z * z + kLightHeight * kLightHeight, cos_theta = kLightHeight / std::sqrt(r2);
  return kRho / kPiD * kIntensity * factor * cos_theta / r2;
}

// Untransformed, the map's pole is +y: the plane below sees θ > π/2, and
// φ = atan2(z, x) runs around it.
TEST(RenderMappedLights, GoniometricLightWeighsEachDirectionByItsTexel) {
  const Image map = ramp_map(16, 8);
  for (const char* integrator : {"direct", "path"}) {
    const Image image = render_lit_plane(R"j({"layout": "goniometric", "file": "map.pfm"})j", map, integrator);
    double worst = 0;
    const int compared = compare(
        image,
        [&](double x, double z, int c) {
          const double r = std::sqrt(x * x + z * z + kLightHeight * kLightHeight);
          double phi = std::atan2(z, x);
          if (phi < 0) phi += 2 * kPiD;
          const double theta = std::acos(-kLightHeight / r);
          return point_light_radiance(x, z, bilinear(map, c, phi / (2 * kPiD), theta / kPiD, true));
        },
        [](double, double) { return true; }, worst);
    EXPECT_EQ(compared, kSize * kSize);
    // 64 stratified positions per pixel of a smooth function (but for the
    // pole's kink under the light): within 0.5 % of the peak.
    EXPECT_LT(worst, 5e-3) << integrator;
  }
}

// Rotated 90° about x, the projection looks down (light +z to world −y), its
// +y towards world +z; its window has the map's 2:1 aspect, the shorter axis
// spanning the 40° field of view.
TEST(RenderMappedLights, ProjectionLightCastsItsImageThroughItsWindow) {
  const Image map = ramp_map(16, 8);
  const double half_y = std::tan(20 * kPiD / 180), half_x = 2 * half_y;
  auto window = [&](double x, double z, double& sx, double& sy) {
    // R_x(90°) maps light (a, b, c) to world (a, −c, b): towards the ground
    // point, world (x, −h, z) / r, is light (x, z, h) / r.
    sx = x / kLightHeight, sy = z / kLightHeight;
    return std::fabs(sx) <= half_x && std::fabs(sy) <= half_y;
  };
  for (const char* integrator : {"direct", "path"}) {
    const Image image = render_lit_plane(
        R"j({"layout": "projection", "file": "map.pfm", "fov": "40 deg",
             "transform": [{"rotate": {"axis": [1, 0, 0], "angle": "90 deg"}}]})j",
        map, integrator);
    double worst = 0;
    const int compared = compare(
        image,
        [&](double x, double z, int c) {
          double sx, sy;
          if (!window(x, z, sx, sy)) return 0.0;
          return point_light_radiance(x, z, bilinear(map, c, 0.5 * (sx / half_x + 1), 0.5 * (sy / half_y + 1), false));
        },
        [&](double x, double z) {
          double sx, sy;
          return window(x, z, sx, sy);
        },
        worst);
    EXPECT_GT(compared, 300);
    EXPECT_LT(worst, 5e-3) << integrator;
  }
}

}  // namespace
}  // namespace safegi::render
