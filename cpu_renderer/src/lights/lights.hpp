// Light sources: point and spot lights (intensity), diffuse area emitters on
// triangle meshes and spheres (radiance) and the environment (radiance from
// every direction), chosen by the scene's LightStrategy (light_choice.hpp).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "lights/environment.hpp"
#include "accel/geometry.hpp"
#include "lights/light_choice.hpp"
#include "safegi/cpu_renderer/emitter_triangles.hpp"
#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::render {

// A point on a light as seen from a shading point.
struct LightSample {
  PointWorld position;
  Real3 position_error;   // metres
  Real3 emitter_normal;   // unit normal of an area light; zero for point lights and the environment
  DirectionWorld wi;       // from the shading point towards the light
  Length distance = sg::zero;
  bool delta = false;      // a point, spot or distant light: no density over directions
  // Point and spot lights: the intensity towards the shading point and the probability
  // of having chosen this light (also for a distant light; with LightStrategy::all,
  // the number of samples the light takes per round).
  Intensity intensity;
  Real probability = 0;
  // A distant light: its irradiance on a surface facing it (its intensity is zero).
  bool directional = false;
  spectrum<dim::irradiance> irradiance;
  // Area lights and the environment: the emitted radiance and the density of
  // this direction, light choice included (with LightStrategy::all, times the
  // light's samples per round: the density of all of them together).
  Radiance radiance;
  PdfSolidAngle pdf = sg::zero;
  uint32_t light = 0;  // which one (Lights' index)
};

// A photon leaving a light: where, which way, and the flux it carries, with
// the light's choice and the densities of its position and direction divided
// out (divide by the number of photons traced for each photon's share).
struct PhotonEmission {
  PointWorld origin;
  Real3 origin_error;    // metres
  Real3 surface_normal;  // the emitter's, oriented along the photon; zero for point lights and the environment
  DirectionWorld direction;
  spectrum<dim::power> flux;
  // The densities divided out of `flux`, apart (the bidirectional path
  // tracer's weights need each): the light, its choice by power, the density
  // of the origin per area (zero for a point light's: a delta) and of the
  // direction per solid angle.
  uint32_t light = 0;
  Real choice = 0;
  PdfArea pdf_position = sg::zero;
  PdfSolidAngle pdf_direction = sg::zero;
};

// The densities with which sample_emission() would emit from a point of a
// light along a direction (PhotonEmission's, for a path found another way).
struct EmissionDensity {
  Real choice = 0;
  PdfArea position = sg::zero;  // zero: a point light's delta
  PdfSolidAngle direction = sg::zero;
};

class Lights {
 public:
  explicit Lights(const Scene& scene, LightStrategy strategy = LightStrategy::power);
  ~Lights();
  Lights(const Lights&) = delete;
  Lights& operator=(const Lights&) = delete;

  bool empty() const { return lights_.empty(); }
  bool has_area_lights() const { return has_area_lights_; }
  uint32_t size() const { return static_cast<uint32_t>(lights_.size()); }
  LightStrategy strategy() const { return strategy_; }
  // With LightStrategy::all: the shadow rays light `index` takes per round.
  int samples_of(uint32_t index) const { return lights_[index].samples; }
  // An area light or the environment: a light whose samples have a density
  // over directions, which a BSDF sample can find too.
  bool has_density(uint32_t index) const {
    const Light::Type type = lights_[index].type;
    return type == Light::Type::triangles || type == Light::Type::sphere || type == Light::Type::environment;
  }
  bool is_environment(uint32_t index) const { return lights_[index].type == Light::Type::environment; }
  // False only when a ray from `origin` along `direction` cannot reach light
  // `index` (it misses a sphere around it): a cheap test before tracing one.
  bool may_be_hit(uint32_t index, PointWorld origin, DirectionWorld direction) const;
  // The light whose surface `hit` is on; -1: none.
  int32_t light_at(const SurfaceHit& hit) const { return light_of_shape_[hit.shape]; }
  // Light `light`'s share of a round at `reference`: the probability of
  // choosing it, or with LightStrategy::all its samples per round. Every
  // density of its samples (LightSample::pdf, pdf(), environment_pdf()) includes it.
  Real weight_of(uint32_t light, PointWorld reference) const;

  // One round of next-event estimation is one sample() (power, uniform or
  // spatial strategy), or samples_of(l) calls of sample_each(l) for every
  // light l (all). The densities of either (pdf(), environment_pdf()) are
  // those of the whole round.

  // One light chosen by the strategy at `reference`, then a point on it, where
  // it is at `time`.
  std::optional<LightSample> sample(PointWorld reference, Time time, Real u_light, Real u1, Real u2) const;
  // A point on light `index` (LightStrategy::all).
  std::optional<LightSample> sample_each(uint32_t index, PointWorld reference, Time time, Real u_within, Real u1,
                                         Real u2) const;

  // Radiance an emissive surface sends back along `incoming` (towards -incoming).
  Radiance emitted(const SurfaceHit& hit, DirectionWorld incoming) const;
  // Solid-angle density with which a round of samples from `reference` would
  // have produced the emitter point `hit` (found at `time`).
  PdfSolidAngle pdf(PointWorld reference, const SurfaceHit& hit, Time time) const;

  // A photon from a light chosen by power, at `time`: a point light's in a
  // uniform direction, an area light's from a uniform point (a side chosen
  // evenly for two-sided ones) in a cosine-distributed direction, the
  // environment's from a disc across the scene's bounding sphere, facing the
  // sampled direction.
  std::optional<PhotonEmission> sample_emission(Time time, Real u_light, Real u1, Real u2, Real u3, Real u4) const;
  // The densities of sample_emission() for light `index` emitting from `point`
  // (an area light's surface point, its normal `normal` as the light's
  // geometry has it; ignored for point and spot lights) along `direction`.
  // Not for the environment and distant lights.
  EmissionDensity emission_density(uint32_t index, const SurfaceHit& point, DirectionWorld direction, Time time) const;
  // Whether light `index` is a point or spot light (a delta in position).
  bool is_point(uint32_t index) const {
    return lights_[index].type == Light::Type::point || lights_[index].type == Light::Type::spot;
  }
  // Whether some light has no emission density over points and directions
  // (the environment, a distant light).
  bool has_directional_lights() const;

  // The environment, seen by a ray that escapes along `direction`, and the
  // density with which sample() picks that direction (light choice included).
  bool has_environment() const { return environment_.has_value(); }
  Radiance environment_radiance(DirectionWorld direction) const { return environment_->radiance(direction); }
  PdfSolidAngle environment_pdf(PointWorld reference, DirectionWorld direction) const;

 private:
  struct Light {
    enum class Type { point, spot, distant, triangles, sphere, environment } type = Type::point;
    PointWorld position;  // point and spot light, sphere centre
    Intensity intensity;  // point and spot light
    SpotLight spot;       // spot light: axis and cone
    const IntensityMap* profile = nullptr;  // point light: its intensity by direction (the scene's)
    DistantLight distant; // distant light: direction and irradiance
    uint32_t first_triangle = 0, triangle_count = 0;
    Length radius = sg::zero;  // sphere
    PdfArea pdf_area = sg::zero;  // 1 / surface area (of a moving emitter: in object space)
    Radiance radiance;
    bool two_sided = false;
    // A moving emitter: index into motions_; its triangles are in object space,
    // its sphere is object_center and object_radius.
    int32_t motion = -1;
    PointObject object_center;
    Length object_radius = sg::zero;
    int samples = 1;  // per round, with LightStrategy::all
    // A sphere around a static area light (may_be_hit); radius 0: none known.
    PointWorld bound_center;
    Length bound_radius = sg::zero;
  };
  // A point on a light: position, its rounding-error box, unit normal, and the
  // density per unit area.
  struct SurfacePoint {
    PointWorld position;
    Real3 position_error;
    NormalWorld normal;
    PdfArea pdf_area = sg::zero;
  };

  template <class Space>
  const EmitterTriangle<Space>& choose_triangle(const std::vector<EmitterTriangle<Space>>& triangles, const Light& light,
                                                Real u) const;
  void sample_surface(uint32_t index, Time time, Real u_triangle, Real u1, Real u2, PointWorld& position,
                      Real3& position_error, NormalWorld& normal, PdfArea& pdf_area) const;
  std::optional<LightSample> sample_light(uint32_t index, Real weight, Real u_within, PointWorld reference, Time time,
                                          Real u1, Real u2) const;
  double estimated_contribution(uint32_t light, PointWorld point, Time time, Real u_within, Real u1, Real u2) const;
  SurfacePoint sample_moving(const Light& light, Time time, Real u_triangle, Real u1, Real u2) const;
  PdfArea moving_pdf_area(const Light& light, const SurfaceHit& hit, Time time) const;

  // The light choice's distribution at `reference`; a light's share of a round.
  std::span<const Real> choice_cdf(PointWorld reference) const;

  std::vector<Light> lights_;
  std::vector<EmitterTriangle<World>> triangles_;
  std::vector<EmitterTriangle<Object>> object_triangles_;  // of moving emitters
  std::vector<RigidMotion> motions_;
  std::vector<Real> power_cdf_;   // photons are emitted by power whatever the strategy
  LightStrategy strategy_;
  std::vector<Real> choice_cdf_;  // power or uniform
  std::unique_ptr<SpatialLightChoice> spatial_;
  std::vector<int32_t> light_of_shape_;
  std::optional<Environment> environment_;
  uint32_t environment_index_ = 0;
  PointWorld scene_center_;  // the bounding sphere of the scene (with an environment or a distant light)
  Length scene_radius_ = sg::zero;
  bool has_area_lights_ = false;  // area lights or the environment: the lights with a density
};

}  // namespace safegi::render
