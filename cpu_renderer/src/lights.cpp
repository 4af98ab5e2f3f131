#include "lights.hpp"

#include <algorithm>

#include "sampling.hpp"

namespace safegi::render {

using kernel::cross;
using kernel::dot;

Lights::Lights(const Scene& scene) : light_of_shape_(scene.shapes.size(), -1) {
  std::vector<float> powers;
  for (const PointLight& point : scene.point_lights) {
    Light light{};
    light.type = Light::Type::point;
    light.position = point.position;
    light.intensity = point.intensity;
    lights_.push_back(light);
    powers.push_back(4 * kPi * point.intensity.average());
  }
  for (uint32_t s = 0; s < scene.shapes.size(); ++s) {
    const Shape& shape = scene.shapes[s];
    if (!shape.emission) continue;
    Light light{};
    light.shape = s;
    light.radiance = *shape.emission;
    light.two_sided = shape.two_sided_emission;
    const Affine& to_world = shape.render_from_object;
    if (shape.type == Shape::Type::sphere) {
      light.type = Light::Type::sphere;
      light.center = to_world.apply_point(shape.center);
      light.radius = shape.radius * kernel::length(Float3{to_world.m[0][0], to_world.m[1][0], to_world.m[2][0]});
      light.area = 4 * kPi * light.radius * light.radius;
    } else {
      light.type = Light::Type::triangles;
      light.first_triangle = static_cast<uint32_t>(triangles_.size());
      double area = 0;
      for (size_t i = 0; i + 2 < shape.indices.size(); i += 3) {
        Float3 a = to_world.apply_point(shape.positions[shape.indices[i]]);
        Float3 b = to_world.apply_point(shape.positions[shape.indices[i + 1]]);
        Float3 c = to_world.apply_point(shape.positions[shape.indices[i + 2]]);
        area += 0.5 * kernel::length(cross(b - a, c - a));
        triangles_.push_back({a, b - a, c - a, static_cast<float>(area)});
      }
      light.triangle_count = static_cast<uint32_t>(triangles_.size()) - light.first_triangle;
      light.area = static_cast<float>(area);
      for (uint32_t t = 0; t < light.triangle_count; ++t) triangles_[light.first_triangle + t].area_cdf /= light.area;
      if (!(light.area > 0)) continue;
    }
    light_of_shape_[s] = static_cast<int32_t>(lights_.size());
    lights_.push_back(light);
    powers.push_back((light.two_sided ? 2 : 1) * kPi * light.area * light.radiance.average());
    has_area_lights_ = true;
  }
  double total = 0;
  for (float p : powers) total += p;
  double running = 0;
  for (float p : powers) {
    running += total > 0 ? p / total : 1.0 / static_cast<double>(powers.size());
    power_cdf_.push_back(static_cast<float>(running));
  }
  if (!power_cdf_.empty()) power_cdf_.back() = 1.0f;
}

float Lights::selection_probability(uint32_t light) const {
  return power_cdf_[light] - (light == 0 ? 0.0f : power_cdf_[light - 1]);
}

uint32_t Lights::choose(float u) const {
  auto found = std::upper_bound(power_cdf_.begin(), power_cdf_.end(), u);
  return static_cast<uint32_t>(std::min<ptrdiff_t>(found - power_cdf_.begin(), power_cdf_.size() - 1));
}

std::optional<LightSample> Lights::sample(Float3 reference, float u_light, float u1, float u2) const {
  if (lights_.empty()) return std::nullopt;
  uint32_t index = choose(u_light);
  const Light& light = lights_[index];
  float probability = selection_probability(index);
  if (!(probability > 0)) return std::nullopt;
  LightSample sample;
  if (light.type == Light::Type::point) {
    Float3 d = light.position - reference;
    float distance2 = dot(d, d);
    if (!(distance2 > 0)) return std::nullopt;
    sample.distance = std::sqrt(distance2);
    sample.wi = d * (1.0f / sample.distance);
    sample.position = light.position;
    sample.incident = light.intensity * (1.0f / distance2);
    sample.pdf = probability;
    sample.delta = true;
    return sample;
  }
  if (light.type == Light::Type::sphere) {
    Float3 n = sample_uniform_sphere(u1, u2);
    sample.normal = n;
    sample.position = light.center + n * light.radius;
    sample.position_error = (kernel::abs(n * light.radius) + kernel::abs(light.center)) * kernel::gamma(6);
  } else {
    // Reuse what is left of u_light to pick a triangle by area.
    float low = index == 0 ? 0.0f : power_cdf_[index - 1];
    float u_triangle = std::min((u_light - low) / probability, 0x1.fffffep-1f);
    const EmitterTriangle* first = triangles_.data() + light.first_triangle;
    const EmitterTriangle* last = first + light.triangle_count;
    const EmitterTriangle* tri =
        std::upper_bound(first, last, u_triangle, [](float u, const EmitterTriangle& t) { return u < t.area_cdf; });
    if (tri == last) tri = last - 1;
    float root = std::sqrt(u1);
    float b1 = 1 - root, b2 = u2 * root;  // uniform over the triangle
    Float3 along_u = tri->e1 * b1, along_v = tri->e2 * b2;
    sample.position = tri->p0 + along_u + along_v;
    sample.position_error = (kernel::abs(tri->p0) + kernel::abs(along_u) + kernel::abs(along_v)) * kernel::gamma(7);
    sample.normal = kernel::normalize(cross(tri->e1, tri->e2));
  }
  Float3 d = sample.position - reference;
  float distance2 = dot(d, d);
  if (!(distance2 > 0)) return std::nullopt;
  sample.distance = std::sqrt(distance2);
  sample.wi = d * (1.0f / sample.distance);
  float cos_light = -dot(sample.normal, sample.wi);
  if (light.two_sided) cos_light = std::fabs(cos_light);
  if (!(cos_light > 0)) return std::nullopt;
  sample.incident = light.radiance;
  // Area density to solid-angle density: dA = r^2 / cos(theta_light) dω.
  sample.pdf = probability / light.area * distance2 / cos_light;
  return sample;
}

Rgb Lights::emitted(const SurfaceHit& hit, Float3 direction) const {
  int32_t index = light_of_shape_[hit.shape];
  if (index < 0) return Rgb(0.0f);
  const Light& light = lights_[index];
  if (!light.two_sided && dot(hit.normal, direction) >= 0) return Rgb(0.0f);
  return light.radiance;
}

float Lights::pdf(Float3 reference, const SurfaceHit& hit) const {
  int32_t index = light_of_shape_[hit.shape];
  if (index < 0) return 0.0f;
  const Light& light = lights_[index];
  Float3 d = hit.position - reference;
  float distance2 = dot(d, d);
  float cos_light = std::fabs(dot(hit.normal, d)) / std::sqrt(distance2);
  if (!(cos_light > 0)) return 0.0f;
  return selection_probability(static_cast<uint32_t>(index)) / light.area * distance2 / cos_light;
}

}  // namespace safegi::render
