// pbrt-v3's GonioPhotometricLight::Scale and ProjectionLight::Projection
// (src/lights/goniometric.h, projection.cpp), and their means over the sphere.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::render {
namespace {

constexpr double kPiD = std::numbers::pi;
constexpr Real kPiR = std::numbers::pi_v<Real>;

// The projection window on the plane z = 1: ±tan(fov/2) across the image's
// shorter axis, its aspect across the longer one.
struct Window {
  double half_x, half_y;
};

Window projection_window(const IntensityMap& profile) {
  const double tangent = std::tan(0.5 * sg::raw(profile.fov));
  const double aspect = profile.map ? static_cast<double>(profile.map->width(0)) / profile.map->height(0) : 1.0;
  return aspect > 1 ? Window{tangent * aspect, tangent} : Window{tangent, tangent / aspect};
}

// The solid angle that the rectangle [0, x] × [0, y] on the plane z = 1 subtends.
double corner_solid_angle(double x, double y) { return std::atan(x * y / std::sqrt(1 + x * x + y * y)); }

double rectangle_solid_angle(double x0, double x1, double y0, double y1) {
  return corner_solid_angle(x1, y1) - corner_solid_angle(x0, y1) - corner_solid_angle(x1, y0) +
         corner_solid_angle(x0, y0);
}

Texel texel_or_one(const IntensityMap& profile, int x, int y) {
  return profile.map ? profile.map->texel(0, x, y) : Texel(1, 1, 1);
}

}  // namespace

Texel intensity_factor(const IntensityMap& profile, DirectionWorld towards) {
  const direction<LightSpace> w = sg::inverse(profile.render_from_light)(towards);
  if (profile.layout == IntensityMap::Layout::goniometric) {
    if (!profile.map) return Texel(1, 1, 1);
    Real phi = std::atan2(w.z(), w.x());
    if (phi < 0) phi += 2 * kPiR;
    const Real theta = std::acos(std::clamp(w.y(), Real(-1), Real(1)));
    return profile.map->bilinear(0, phi / (2 * kPiR), theta / kPiR);
  }
  if (!(w.z() >= Real(1e-3))) return Texel{};  // behind the light, or beyond pbrt-v3's near plane
  const Window window = projection_window(profile);
  const double x = w.x() / w.z(), y = w.y() / w.z();
  if (!(std::fabs(x) <= window.half_x && std::fabs(y) <= window.half_y)) return Texel{};
  if (!profile.map) return Texel(1, 1, 1);
  const Real s = static_cast<Real>(0.5 * (x / window.half_x + 1)), t = static_cast<Real>(0.5 * (y / window.half_y + 1));
  return profile.map->bilinear(0, s, t);
}

// Each texel weighted by the solid angle it covers (not pbrt-v3's plain texel
// mean, which over-weights a lat-long map's poles).
Texel mean_intensity_factor(const IntensityMap& profile) {
  const int width = profile.map ? profile.map->width(0) : 1, height = profile.map ? profile.map->height(0) : 1;
  const Window window = projection_window(profile);
  const double dx = 2 * window.half_x / width, dy = 2 * window.half_y / height;
  double sum[3] = {0, 0, 0};
  for (int y = 0; y < height; ++y) {
    double row_solid_angle = 0;  // of each texel in the row
    if (profile.layout == IntensityMap::Layout::goniometric) {
      row_solid_angle = 2 * kPiD / width * (std::cos(kPiD * y / height) - std::cos(kPiD * (y + 1) / height));
    }
    for (int x = 0; x < width; ++x) {
      double solid_angle = row_solid_angle;
      if (profile.layout == IntensityMap::Layout::projection) {
        solid_angle = rectangle_solid_angle(-window.half_x + x * dx, -window.half_x + (x + 1) * dx,
                                            -window.half_y + y * dy, -window.half_y + (y + 1) * dy);
      }
      const sg::vec3_rep texel = sg::raw(texel_or_one(profile, x, y));
      for (int c = 0; c < 3; ++c) sum[c] += solid_angle * texel[c];
    }
  }
  const double sphere = 4 * kPiD;
  return Texel(static_cast<Real>(sum[0] / sphere), static_cast<Real>(sum[1] / sphere), static_cast<Real>(sum[2] / sphere));
}

}  // namespace safegi::render
