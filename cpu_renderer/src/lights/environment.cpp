#include "lights/environment.hpp"

#include <cmath>

namespace safegi::render {

Environment::Environment(const EnvironmentLight& light)
    : light_(light), light_from_render_(sg::inverse(light.render_from_light)) {
  if (!light.map) return;
  // Each texel cell weighted by the luminance near it (its 3×3 neighbourhood:
  // bilinear lookups blend neighbours, so a black texel next to a bright one
  // still has radiance in its cell) times sin θ, the map's area stretch.
  const MipMap& map = *light.map;
  const int width = map.width(0), height = map.height(0);
  std::vector<Real> weights(static_cast<size_t>(width) * height);
  for (int y = 0; y < height; ++y) {
    Real sin_theta = std::sin(kPi * (static_cast<Real>(y) + Real(0.5)) / static_cast<Real>(height));
    for (int x = 0; x < width; ++x) {
      Real sum = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) sum += sg::luminance(map.texel(0, x + dx, y + dy));
      weights[static_cast<size_t>(y) * width + x] = sum / 9 * sin_theta;
    }
  }
  distribution_.emplace(weights, width, height);
}

Environment::MapPoint Environment::to_map(DirectionWorld wi) const {
  direction<LightSpace> w = light_from_render_(wi);
  Real z = std::clamp(w.z(), Real(-1), Real(1));
  Real phi = std::atan2(w.y(), w.x());
  if (phi < 0) phi += 2 * kPi;
  Real theta = std::acos(z);
  // sin θ from x and y: better conditioned than sqrt(1 − z²) near the poles.
  return {phi / (2 * kPi), theta / kPi, std::sqrt(w.x() * w.x() + w.y() * w.y())};
}

Radiance Environment::radiance(DirectionWorld wi) const {
  if (!light_.map) return light_.radiance;
  MapPoint p = to_map(wi);
  return light_.radiance * light_.map->bilinear(0, p.u, p.v);
}

std::optional<Environment::Sample> Environment::sample(Real u1, Real u2) const {
  Sample sample;
  if (!distribution_) {
    sample.wi = light_.render_from_light(from_kernel<direction<LightSpace>>(sample_uniform_sphere(u1, u2)));
    sample.radiance = light_.radiance;
    sample.pdf = 1 / (4 * kPi * units::steradian);
    return sample;
  }
  Real u, v, map_density;
  distribution_->sample(u1, u2, u, v, map_density);
  const Real theta = v * kPi, phi = u * 2 * kPi;
  const Real sin_theta = std::sin(theta);
  if (!(sin_theta > 0) || !(map_density > 0)) return std::nullopt;
  direction<LightSpace> w(sin_theta * std::cos(phi), sin_theta * std::sin(phi), std::cos(theta));
  sample.wi = light_.render_from_light(w);
  sample.radiance = light_.radiance * light_.map->bilinear(0, u, v);
  sample.pdf = map_density / solid_angle_per_map_area(sin_theta);
  return sample;
}

PdfSolidAngle Environment::pdf(DirectionWorld wi) const {
  if (!distribution_) return 1 / (4 * kPi * units::steradian);
  MapPoint p = to_map(wi);
  if (!(p.sin_theta > 0)) return sg::zero;
  return distribution_->density(p.u, p.v) / solid_angle_per_map_area(p.sin_theta);
}

Radiance Environment::average_radiance() const {
  if (!light_.map) return light_.radiance;
  // Texels weighted by the solid angle of their row.
  const MipMap& map = *light_.map;
  Texel sum;
  Real weight = 0;
  for (int y = 0; y < map.height(0); ++y) {
    Real sin_theta = std::sin(kPi * (static_cast<Real>(y) + Real(0.5)) / static_cast<Real>(map.height(0)));
    for (int x = 0; x < map.width(0); ++x) sum += map.texel(0, x, y) * sin_theta;
    weight += sin_theta * static_cast<Real>(map.width(0));
  }
  return light_.radiance * (sum / weight);
}

}  // namespace safegi::render
