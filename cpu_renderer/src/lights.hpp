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
  Float3 position;
  Float3 position_error;
  Float3 normal;          // emitter normal; zero for point lights
  Float3 wi;              // unit direction from the shading point to the light
  float distance = 0;
  // Area lights: emitted radiance towards the shading point and the density of
  // choosing this light and this direction, per solid angle.
  // Point lights: intensity / distance^2 (irradiance at normal incidence) and
  // the probability of choosing this light.
  Rgb incident;
  float pdf = 0;
  bool delta = false;
};

class Lights {
 public:
  Lights(const Scene& scene);

  bool empty() const { return lights_.empty(); }
  bool has_area_lights() const { return has_area_lights_; }

  // One light chosen by power, then a point on it.
  std::optional<LightSample> sample(Float3 reference, float u_light, float u1, float u2) const;

  // Radiance leaving an emissive shape at `hit` towards `-direction`.
  Rgb emitted(const SurfaceHit& hit, Float3 direction) const;
  // Solid-angle density with which sample() would have produced the emitter
  // point `hit` as seen from `reference`.
  float pdf(Float3 reference, const SurfaceHit& hit) const;

 private:
  struct Light {
    enum class Type { point, triangles, sphere } type;
    Float3 position;  // point light
    Rgb intensity;    // point light
    uint32_t shape = 0;
    uint32_t first_triangle = 0, triangle_count = 0;
    Float3 center;  // sphere
    float radius = 0;
    float area = 0;
    Rgb radiance;
    bool two_sided = false;
  };
  struct EmitterTriangle {
    Float3 p0, e1, e2;
    float area_cdf;  // cumulative area within its light, normalised to 1 at its last triangle
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
