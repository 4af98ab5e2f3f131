// A loaded scene: every physical value already in reference units (m, s, J,
// rad, sr) and every geometric value tagged with the space it lives in.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "safegi/cpu_renderer/types.hpp"

namespace safegi::render {

struct Material {
  enum class Type { lambert, phong, mirror, black };
  Type type = Type::black;
  Reflectance diffuse{};   // Lambert albedo, Phong diffuse part
  Reflectance specular{};  // Phong specular part, mirror tint
  float exponent = 1.0f;       // Phong lobe exponent (dimensionless)
  std::string name;
};

struct Shape {
  enum class Type { mesh, sphere };
  Type type = Type::mesh;
  std::string name;
  // mesh: triangles over positions in object space
  std::vector<PointObject> positions;
  std::vector<uint32_t> indices;
  // sphere, in object space
  PointObject center;
  Length radius = sg::zero;

  int material = -1;  // index into Scene::materials; -1: absorbs everything
  std::optional<Radiance> emission;
  bool two_sided_emission = false;

  ObjectToWorld render_from_object;
  // Rigid motion: where the object is at shutter close (absent: static).
  std::optional<ObjectToWorld> render_from_object_at_close;
};

struct PointLight {
  PointWorld position;
  Intensity intensity;
};

// A spot light as pbrt-v3 defines it: intensity I (on its axis) times a
// falloff of the angle θ to the axis — 1 up to cone_angle − cone_delta, then
// δ⁴ with δ = (cos θ − cos cone_angle) / (cos(cone_angle − cone_delta) − cos cone_angle),
// and 0 beyond cone_angle.
struct SpotLight {
  PointWorld position;
  DirectionWorld direction;
  Intensity intensity;
  Angle cone_angle = sg::zero;
  Angle cone_delta = sg::zero;
};

// The spot's falloff towards a direction at cos θ to its axis.
inline float spot_falloff(const SpotLight& light, float cos_theta) {
  float cos_total = sg::cos(light.cone_angle), cos_start = sg::cos(light.cone_angle - light.cone_delta);
  if (cos_theta < cos_total) return 0;
  if (cos_theta >= cos_start) return 1;
  float delta = (cos_theta - cos_total) / (cos_start - cos_total);
  return (delta * delta) * (delta * delta);
}

struct Camera {
  PointWorld position;
  PointWorld look_at;
  DirectionWorld up;
  Angle fov = sg::zero;  // across the shorter image axis
  Length lens_radius = sg::zero;
  Length focus_distance = sg::zero;
  Time shutter_open = sg::zero;
  Time shutter_close = sg::zero;
};

enum class IntegratorType { direct, path };

struct RenderSettings {
  int width = 256;
  int height = 256;
  int spp = 16;
  int max_depth = 65;
  IntegratorType integrator = IntegratorType::path;
  // Knobs of the speed/accuracy study; every combination is unbiased.
  bool mis = true;                 // off: area lights by light sampling only (BSDF rays ignore their emission)
  int light_samples = 1;           // shadow rays per shading point for direct lighting
  bool russian_roulette = true;    // off: paths end only at max_depth or when nothing is hit
  int russian_roulette_depth = 3;  // bounces before Russian roulette starts
};

struct Scene {
  RenderSettings settings;
  Camera camera;
  std::vector<Material> materials;
  std::vector<Shape> shapes;
  std::vector<PointLight> point_lights;
  std::vector<SpotLight> spot_lights;
};

}  // namespace safegi::render
