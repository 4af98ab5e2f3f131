// Light sources: point lights (intensity) and diffuse area emitters on
// triangle meshes and spheres (radiance), chosen in proportion to power.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "geometry.hpp"
#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::render {

// A point on a light as seen from a shading point.
struct LightSample {
  PointWorld position;
  Float3 position_error;   // metres
  Float3 emitter_normal;   // unit normal of an area light; zero for point lights
  DirectionWorld wi;       // from the shading point towards the light
  Length distance = sg::zero;
  bool delta = false;      // a point light: no density over directions
  // Point lights: the intensity towards the shading point and the probability
  // of having chosen this light.
  Intensity intensity;
  float probability = 0;
  // Area lights: the emitted radiance and the density of this direction,
  // light choice included.
  Radiance radiance;
  PdfSolidAngle pdf = sg::zero;
};

class Lights {
 public:
  explicit Lights(const Scene& scene);

  bool empty() const { return lights_.empty(); }
  bool has_area_lights() const { return has_area_lights_; }

  // One light chosen by power, then a point on it.
  std::optional<LightSample> sample(PointWorld reference, float u_light, float u1, float u2) const;

  // Radiance an emissive surface sends back along `incoming` (towards -incoming).
  Radiance emitted(const SurfaceHit& hit, DirectionWorld incoming) const;
  // Solid-angle density with which sample() would have produced the emitter
  // point `hit` as seen from `reference`.
  PdfSolidAngle pdf(PointWorld reference, const SurfaceHit& hit) const;

 private:
  struct Light {
    enum class Type { point, triangles, sphere } type = Type::point;
    PointWorld position;  // point light, sphere centre
    Intensity intensity;  // point light
    uint32_t first_triangle = 0, triangle_count = 0;
    Length radius = sg::zero;  // sphere
    PdfArea pdf_area = sg::zero;  // 1 / surface area
    Radiance radiance;
    bool two_sided = false;
  };
  struct EmitterTriangle {
    PointWorld p0;
    VectorWorld e1, e2;
    float area_cdf;  // cumulative area within its light, 1 at its last triangle
  };

  float selection_probability(uint32_t light) const;
  uint32_t choose(float u) const;

  std::vector<Light> lights_;
  std::vector<EmitterTriangle> triangles_;
  std::vector<float> power_cdf_;
  std::vector<int32_t> light_of_shape_;
  bool has_area_lights_ = false;
};

}  // namespace safegi::render
