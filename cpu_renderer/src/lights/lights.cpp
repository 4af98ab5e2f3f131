#include "lights/lights.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "safegi/cpu_renderer/sampling.hpp"

namespace safegi::render {

namespace {

// The cone a sphere subtends from a point outside it (pbrt-v3's Sphere::Sample(ref, u),
// with pbrt-v4's cancellation-free forms): 1 − cos θmax, nothing from inside or on it
// (or when the cone is too narrow for Real), where the caller samples by area.
std::optional<Real> cone_one_minus_cos(PointWorld center, Length radius, PointWorld reference) {
  const Real dc = sg::raw(sg::distance(center, reference)), r = sg::raw(radius);
  if (!(dc > r * Real(1.0001))) return std::nullopt;
  const Real sin2_max = (r / dc) * (r / dc);
  const Real one_minus_cos = sin2_max / (1 + std::sqrt(std::max(Real(0), 1 - sin2_max)));
  if (!(one_minus_cos > 0)) return std::nullopt;
  return one_minus_cos;
}

PdfSolidAngle cone_pdf(Real one_minus_cos) { return 1 / (2 * sg::pi * one_minus_cos * units::steradian); }

// A direction uniform in that cone, and the sphere's nearer point along it: its outward unit normal.
DirectionWorld cone_point_normal(PointWorld center, Length radius, PointWorld reference, Real one_minus_cos, Real u1,
                                 Real u2) {
  using V = sg::vec3_rep;
  const V to_center(sg::raw(center - reference));
  const Real dc = glm::length(to_center), sin_max = sg::raw(radius) / dc;
  const Real one_minus_cos_theta = u1 * one_minus_cos;
  const Real cos_theta = 1 - one_minus_cos_theta;
  const Real sin2_theta = one_minus_cos_theta * (2 - one_minus_cos_theta);
  // The angle at the centre between the reference and the point (pbrt-v4's form).
  const Real cos_alpha = sin2_theta / sin_max + cos_theta * std::sqrt(std::max(Real(0), 1 - sin2_theta / (sin_max * sin_max)));
  const Real sin_alpha = std::sqrt(std::max(Real(0), 1 - cos_alpha * cos_alpha));
  const Real phi = u2 * 2 * sg::pi;
  const V w = to_center / dc;
  const V a = std::fabs(w.x) > std::fabs(w.y) ? V(-w.z, 0, w.x) / std::sqrt(w.x * w.x + w.z * w.z)
                                              : V(0, w.z, -w.y) / std::sqrt(w.y * w.y + w.z * w.z);
  const V b = glm::cross(w, a);
  const V outward = -(sin_alpha * std::cos(phi) * a + sin_alpha * std::sin(phi) * b + cos_alpha * w);
  return from_kernel<DirectionWorld>(kernel::Real3{outward.x, outward.y, outward.z});
}

// The box around every static shape (at the shutter-open pose).
kernel::Bounds3 scene_bounds(const Scene& scene) {
  kernel::Bounds3 bounds;
  for (const Shape& shape : scene.shapes) {
    if (shape.type == Shape::Type::sphere) {
      Real3 center = to_kernel(shape.render_from_object(shape.center));
      Real r = sg::raw(placed_radius(shape.render_from_object, shape.radius));
      bounds.extend(center - Real3{r, r, r});
      bounds.extend(center + Real3{r, r, r});
    } else {
      for (const PointObject& p : shape.positions) bounds.extend(to_kernel(shape.render_from_object(p)));
    }
  }
  if (bounds.empty()) bounds.extend(Real3{0, 0, 0});
  return bounds;
}

// A sphere around that box.
void scene_bounding_sphere(const Scene& scene, PointWorld& center, Length& radius) {
  const kernel::Bounds3 bounds = scene_bounds(scene);
  center = from_kernel<PointWorld>(bounds.centroid());
  radius = sg::from_raw<Length>(std::max(Real(0.5) * kernel::length(bounds.extent()), std::numeric_limits<Real>::min()));
}

}  // namespace

Lights::Lights(const Scene& scene, LightStrategy strategy)
    : strategy_(strategy), light_of_shape_(scene.shapes.size(), -1) {
  std::vector<double> powers;  // watts, averaged over the channels
  for (const PointLight& point : scene.point_lights) {
    Light light;
    light.type = Light::Type::point;
    light.position = point.position;
    light.intensity = point.intensity;
    light.profile = point.profile ? &*point.profile : nullptr;
    lights_.push_back(light);
    const Intensity mean = point.profile ? point.intensity * mean_intensity_factor(*point.profile) : point.intensity;
    powers.push_back(sg::raw(sg::average(mean) * (4 * sg::pi * units::steradian)));
  }
  for (const SpotLight& spot : scene.spot_lights) {
    Light light;
    light.type = Light::Type::spot;
    light.position = spot.position;
    light.intensity = spot.intensity;
    light.spot = spot;
    lights_.push_back(light);
    // pbrt-v3's SpotLight::Power: the full cone at I, the falloff band at half.
    Real cos_total = sg::cos(spot.cone_angle), cos_start = sg::cos(spot.cone_angle - spot.cone_delta);
    auto cone = (2 * sg::pi * (1 - Real(0.5) * (cos_start + cos_total))) * units::steradian;
    powers.push_back(sg::raw(sg::average(spot.intensity) * cone));
  }
  if (scene.environment || !scene.distant_lights.empty()) scene_bounding_sphere(scene, scene_center_, scene_radius_);
  for (const DistantLight& distant : scene.distant_lights) {
    Light light;
    light.type = Light::Type::distant;
    light.distant = distant;
    lights_.push_back(light);
    // pbrt-v3's DistantLight::Power: the flux through a disc across the scene's bounding sphere.
    powers.push_back(sg::raw(sg::average(distant.irradiance) * (sg::pi * scene_radius_ * scene_radius_)));
  }
  for (uint32_t s = 0; s < scene.shapes.size(); ++s) {
    const Shape& shape = scene.shapes[s];
    if (!shape.emission) continue;
    Light light;
    light.radiance = *shape.emission;
    light.two_sided = shape.two_sided_emission;
    const RenderFromObject& render_from_object = shape.render_from_object;
    quantity<dim::area> area = sg::zero;
    if (shape.type == Shape::Type::sphere) {
      light.type = Light::Type::sphere;
      light.position = render_from_object(shape.center);
      light.radius = placed_radius(render_from_object, shape.radius);
      area = 4 * sg::pi * light.radius * light.radius;
    } else {
      light.type = Light::Type::triangles;
      light.first_triangle = static_cast<uint32_t>(triangles_.size());
      area = append_emitter_triangles(shape, render_from_object, triangles_);
      light.triangle_count = static_cast<uint32_t>(triangles_.size()) - light.first_triangle;
    }
    if (!(area > sg::zero)) continue;
    light.pdf_area = 1.0f / area;
    light.samples = shape.emission_samples;
    if (std::optional<RigidMotion> motion = motion_of(shape, scene.camera)) {
      // Power (for choosing lights) stays that of the shutter-open pose; points
      // are sampled where the emitter is at the ray's time.
      light.motion = static_cast<int32_t>(motions_.size());
      motions_.push_back(*motion);
      light.object_center = shape.center;
      light.object_radius = shape.radius;
      if (light.type == Light::Type::triangles) {
        light.first_triangle = static_cast<uint32_t>(object_triangles_.size());
        quantity<dim::area> object_area =
            append_emitter_triangles(shape, [](PointObject p) { return p; }, object_triangles_);
        light.pdf_area = 1.0f / object_area;
      }
    }
    if (light.motion < 0) {
      kernel::Bounds3 bounds;
      if (light.type == Light::Type::sphere) {
        const Real r = sg::raw(light.radius);
        bounds.extend(to_kernel(light.position) - Real3{r, r, r});
        bounds.extend(to_kernel(light.position) + Real3{r, r, r});
      }
      for (uint32_t t = 0; light.type == Light::Type::triangles && t < light.triangle_count; ++t) {
        const EmitterTriangle<World>& triangle = triangles_[light.first_triangle + t];
        for (PointWorld p : {triangle.p0, triangle.p0 + triangle.e1, triangle.p0 + triangle.e2}) bounds.extend(to_kernel(p));
      }
      light.bound_center = from_kernel<PointWorld>(bounds.centroid());
      light.bound_radius = sg::from_raw<Length>(Real(0.5) * kernel::length(bounds.extent()));
    }
    light_of_shape_[s] = static_cast<int32_t>(lights_.size());
    lights_.push_back(light);
    // A diffuse emitter radiates π·A·L per side.
    auto power = sg::average(light.radiance) * area * (sg::pi * units::steradian * units::proj);
    powers.push_back((light.two_sided ? 2 : 1) * sg::raw(power));
    has_area_lights_ = true;
  }
  if (scene.environment) {
    // Choose the environment by the flux it sends into the scene's bounding
    // sphere, π · L̄ · 4πr² (any positive weight would be unbiased).
    environment_.emplace(*scene.environment);
    Light light;
    light.type = Light::Type::environment;
    light.samples = scene.environment->samples;
    environment_index_ = static_cast<uint32_t>(lights_.size());
    lights_.push_back(light);
    Length radius = scene_radius_;
    auto flux = sg::average(environment_->average_radiance()) * (4 * sg::pi * radius * radius) *
                (sg::pi * units::steradian * units::proj);
    powers.push_back(sg::raw(flux));
    has_area_lights_ = true;
  }
  power_cdf_ = light_cdf(powers);
  if (strategy_ == LightStrategy::uniform) choice_cdf_ = light_cdf(std::vector<double>(powers.size(), 1.0));
  else choice_cdf_ = power_cdf_;  // and where a voxel has nothing better (spatial)
  if (strategy_ == LightStrategy::spatial && lights_.size() > 1) {
    const Time time = scene.camera.shutter_open;
    spatial_ = std::make_unique<SpatialLightChoice>(
        scene_bounds(scene), static_cast<uint32_t>(lights_.size()),
        [this, time](uint32_t light, PointWorld point, Real u_within, Real u1, Real u2) {
          return estimated_contribution(light, point, time, u_within, u1, u2);
        });
  }
}

Lights::~Lights() = default;

std::span<const Real> Lights::choice_cdf(PointWorld reference) const {
  return spatial_ ? spatial_->cdf_at(reference) : std::span<const Real>(choice_cdf_);
}

Real Lights::weight_of(uint32_t light, PointWorld reference) const {
  if (strategy_ == LightStrategy::all) return static_cast<Real>(lights_[light].samples);
  return light_probability(choice_cdf(reference), light);
}

// pbrt-v3's estimate for its spatial light choice: the light's radiance (or a
// point light's irradiance) at `point` over the density of the sample, averaged
// over the channels, whatever the surface there.
double Lights::estimated_contribution(uint32_t light, PointWorld point, Time time, Real u_within, Real u1,
                                      Real u2) const {
  std::optional<LightSample> s = sample_light(light, 1, u_within, point, time, u1, u2);
  if (!s) return 0;
  if (s->directional) return sg::raw(sg::average(s->irradiance));
  if (s->delta) return sg::raw(sg::average(s->intensity * sg::solid_angle_per_projected_area(s->distance)));
  if (!(s->pdf > sg::zero)) return 0;
  return sg::raw(sg::average(s->radiance) / s->pdf);
}

template <class Space>
const EmitterTriangle<Space>& Lights::choose_triangle(const std::vector<EmitterTriangle<Space>>& triangles,
                                                      const Light& light, Real u) const {
  const EmitterTriangle<Space>* first = triangles.data() + light.first_triangle;
  return *choose_emitter_triangle(first, first + light.triangle_count, u);
}

// The emitter at `time`: a sphere where its centre and radius have moved; a
// mesh point drawn by object-space area, whose density per world area divides
// by the area the motion's pose stretches it to.
Lights::SurfacePoint Lights::sample_moving(const Light& light, Time time, Real u_triangle, Real u1, Real u2) const {
  const RigidMotion& motion = motions_[light.motion];
  RenderFromObject render_from_object = motion.render_from_object(time);
  SurfacePoint point;
  if (light.type == Light::Type::sphere) {
    PointWorld center = render_from_object(light.object_center);
    Length radius = placed_radius(render_from_object, light.object_radius);
    DirectionWorld outward = from_kernel<DirectionWorld>(sample_uniform_sphere(u1, u2));
    point.normal = sg::to_normal(outward);
    VectorWorld offset = outward * radius;
    point.position = center + offset;
    point.position_error = (kernel::abs(to_kernel(offset)) + kernel::abs(to_kernel(center))) * kernel::gamma(8);
    point.pdf_area = 1.0f / (4 * sg::pi * radius * radius);
    return point;
  }
  const EmitterTriangle<Object>& tri = choose_triangle(object_triangles_, light, u_triangle);
  TriangleWeights b = uniform_triangle_weights(u1, u2);
  VectorWorld e1 = render_from_object(tri.e1), e2 = render_from_object(tri.e2);
  PointWorld p0 = render_from_object(tri.p0);
  VectorWorld along_u = e1 * b.along_e1, along_v = e2 * b.along_e2;
  point.position = p0 + along_u + along_v;
  // The triangle's error plus the pose's (a 3x4 affine map: γ(3) of the terms).
  point.position_error = (kernel::abs(to_kernel(p0)) + kernel::abs(to_kernel(along_u)) + kernel::abs(to_kernel(along_v))) *
                         kernel::gamma(10);
  point.normal = sg::to_normal(sg::normalize(sg::cross(e1, e2)));
  point.pdf_area = light.pdf_area / area_scale(motion.at(sg::raw(time)), to_kernel(point.normal));
  return point;
}

// A point on area light `index`, u_triangle picking the triangle by area: its
// position, rounding-error box, unit normal and density per area. (Inlined
// into both callers, writing straight into theirs: next-event estimation runs
// it once per shadow ray.)
[[gnu::always_inline]] inline void Lights::sample_surface(uint32_t index, Time time, Real u_triangle, Real u1, Real u2,
                                                          PointWorld& position, Real3& position_error,
                                                          NormalWorld& normal, PdfArea& pdf_area) const {
  const Light& light = lights_[index];
  u_triangle = std::min(u_triangle, Real(0x1.fffffep-1f));
  pdf_area = light.pdf_area;
  if (light.motion >= 0) {
    SurfacePoint point = sample_moving(light, time, u_triangle, u1, u2);
    position = point.position;
    position_error = point.position_error;
    normal = point.normal;
    pdf_area = point.pdf_area;
  } else if (light.type == Light::Type::sphere) {
    DirectionWorld outward = from_kernel<DirectionWorld>(sample_uniform_sphere(u1, u2));
    normal = sg::to_normal(outward);
    VectorWorld offset = outward * light.radius;
    position = light.position + offset;
    position_error = (kernel::abs(to_kernel(offset)) + kernel::abs(to_kernel(light.position))) * kernel::gamma(6);
  } else {
    const EmitterTriangle<World>& tri = choose_triangle(triangles_, light, u_triangle);
    TriangleWeights b = uniform_triangle_weights(u1, u2);
    VectorWorld along_u = tri.e1 * b.along_e1, along_v = tri.e2 * b.along_e2;
    position = tri.p0 + along_u + along_v;
    position_error =
        (kernel::abs(to_kernel(tri.p0)) + kernel::abs(to_kernel(along_u)) + kernel::abs(to_kernel(along_v))) *
        kernel::gamma(7);
    normal = sg::to_normal(sg::normalize(sg::cross(tri.e1, tri.e2)));
  }
}

std::optional<LightSample> Lights::sample(PointWorld reference, Time time, Real u_light, Real u1, Real u2) const {
  if (lights_.empty()) return std::nullopt;
  const ChosenLight chosen = choose_light(choice_cdf(reference), u_light);
  if (!(chosen.probability > 0)) return std::nullopt;
  return sample_light(chosen.index, chosen.probability, chosen.u_within, reference, time, u1, u2);
}

std::optional<LightSample> Lights::sample_each(uint32_t index, PointWorld reference, Time time, Real u_within, Real u1,
                                               Real u2) const {
  return sample_light(index, static_cast<Real>(lights_[index].samples), u_within, reference, time, u1, u2);
}

// A point on light `index`, whose densities are scaled by `weight`: the
// probability of having chosen it, or the number of samples it takes.
std::optional<LightSample> Lights::sample_light(uint32_t index, Real weight, Real u_within, PointWorld reference,
                                                Time time, Real u1, Real u2) const {
  const Light& light = lights_[index];
  LightSample sample;
  sample.light = index;
  if (light.type == Light::Type::environment) {
    std::optional<Environment::Sample> direction = environment_->sample(u1, u2);
    if (!direction) return std::nullopt;
    // The shadow ray runs to a point beyond the scene's bounding sphere (as pbrt's).
    sample.wi = direction->wi;
    sample.radiance = direction->radiance;
    sample.pdf = weight * direction->pdf;
    sample.distance = sg::distance(reference, scene_center_) + 2 * scene_radius_;
    sample.position = reference + sample.wi * sample.distance;
    sample.position_error = kernel::abs(to_kernel(sample.position)) * kernel::gamma(4);
    return sample;
  }
  if (light.type == Light::Type::distant) {
    // The shadow ray runs past the scene's bounding sphere, as the environment's.
    sample.wi = light.distant.direction;
    sample.distance = sg::distance(reference, scene_center_) + 2 * scene_radius_;
    sample.position = reference + sample.wi * sample.distance;
    sample.position_error = kernel::abs(to_kernel(sample.position)) * kernel::gamma(4);
    sample.irradiance = light.distant.irradiance;
    sample.directional = true;
    sample.probability = weight;
    sample.delta = true;
    return sample;
  }
  if (light.type == Light::Type::point || light.type == Light::Type::spot) {
    VectorWorld toward = light.position - reference;
    sample.distance = sg::length(toward);
    if (!(sample.distance > sg::zero)) return std::nullopt;
    sample.wi = sg::normalize(toward);
    sample.position = light.position;
    sample.intensity = light.intensity;
    if (light.profile) {
      sample.intensity = light.intensity * intensity_factor(*light.profile, -sample.wi);
      if (!(sg::max_component(sample.intensity) > sg::zero)) return std::nullopt;
    }
    if (light.type == Light::Type::spot) {
      Real falloff = spot_falloff(light.spot, -sg::dot(light.spot.direction, sample.wi));
      if (!(falloff > 0)) return std::nullopt;
      sample.intensity = light.intensity * falloff;
    }
    sample.probability = weight;
    sample.delta = true;
    return sample;
  }
  if (light.type == Light::Type::sphere && light.motion < 0) {
    // Seen from outside, a sphere is sampled by the cone it subtends: every sample lands on
    // the side facing the reference, with the density of a direction, not of an area.
    if (std::optional<Real> one_minus_cos = cone_one_minus_cos(light.position, light.radius, reference)) {
      DirectionWorld outward = cone_point_normal(light.position, light.radius, reference, *one_minus_cos, u1, u2);
      VectorWorld offset = outward * light.radius;
      sample.position = light.position + offset;
      sample.position_error = (kernel::abs(to_kernel(offset)) + kernel::abs(to_kernel(light.position))) * kernel::gamma(6);
      VectorWorld toward = sample.position - reference;
      sample.distance = sg::length(toward);
      if (!(sample.distance > sg::zero)) return std::nullopt;
      sample.wi = sg::normalize(toward);
      sample.emitter_normal = to_kernel(outward);
      sample.radiance = light.radiance;
      sample.pdf = weight * cone_pdf(*one_minus_cos);
      return sample;
    }
  }
  NormalWorld normal;
  PdfArea pdf_area = sg::zero;
  sample_surface(index, time, u_within, u1, u2, sample.position, sample.position_error, normal, pdf_area);
  VectorWorld toward = sample.position - reference;
  sample.distance = sg::length(toward);
  if (!(sample.distance > sg::zero)) return std::nullopt;
  sample.wi = sg::normalize(toward);
  Proj cos_light = -sg::dot(normal, sample.wi);
  if (light.two_sided) cos_light = sg::abs(cos_light);
  if (!(cos_light > sg::zero)) return std::nullopt;
  sample.emitter_normal = to_kernel(normal);
  sample.radiance = light.radiance;
  sample.pdf = weight * sg::pdf_area_to_solid_angle(pdf_area, sample.distance * sample.distance, normal, sample.wi);
  return sample;
}

Radiance Lights::emitted(const SurfaceHit& hit, DirectionWorld incoming) const {
  int32_t index = light_of_shape_[hit.shape];
  if (index < 0) return Radiance{};
  const Light& light = lights_[index];
  if (!light.two_sided && sg::dot(hit.normal, incoming) >= sg::zero) return Radiance{};
  return light.radiance;
}

bool Lights::may_be_hit(uint32_t index, PointWorld origin, DirectionWorld direction) const {
  const Light& light = lights_[index];
  if (!(light.bound_radius > sg::zero)) return true;
  const VectorWorld to_center = light.bound_center - origin;
  const Length along = sg::dot(to_center, direction);
  // Widened for the rounding of this test and of the box (relative 1e-3 of either size).
  const Length reach = light.bound_radius * Real(1.001) + sg::length(to_center) * Real(1e-3);
  if (along < -reach) return false;
  return sg::length_squared(to_center) - along * along <= reach * reach;
}

PdfSolidAngle Lights::pdf(PointWorld reference, const SurfaceHit& hit, Time time) const {
  int32_t index = light_of_shape_[hit.shape];
  if (index < 0) return sg::zero;
  const Light& light = lights_[index];
  if (light.type == Light::Type::sphere && light.motion < 0)
    if (std::optional<Real> one_minus_cos = cone_one_minus_cos(light.position, light.radius, reference))
      return weight_of(static_cast<uint32_t>(index), reference) * cone_pdf(*one_minus_cos);
  VectorWorld toward = hit.position - reference;
  Proj cos_light = sg::abs_dot(hit.normal, sg::normalize(toward));
  if (!(cos_light > sg::zero)) return sg::zero;
  return weight_of(static_cast<uint32_t>(index), reference) *
         sg::pdf_area_to_solid_angle(light.motion < 0 ? light.pdf_area : moving_pdf_area(light, hit, time),
                                     sg::length_squared(toward), hit.normal, sg::normalize(toward));
}

std::optional<PhotonEmission> Lights::sample_emission(Time time, Real u_light, Real u1, Real u2, Real u3,
                                                      Real u4) const {
  if (lights_.empty()) return std::nullopt;
  const ChosenLight chosen = choose_light(power_cdf_, u_light);
  const uint32_t index = chosen.index;
  const Light& light = lights_[index];
  const Real probability = chosen.probability;
  if (!(probability > 0)) return std::nullopt;
  PhotonEmission photon;
  photon.light = index;
  photon.choice = probability;
  if (light.type == Light::Type::point || light.type == Light::Type::spot) {
    photon.origin = light.position;
    photon.origin_error = kernel::abs(to_kernel(light.position)) * kernel::gamma(1);
    photon.direction = from_kernel<DirectionWorld>(sample_uniform_sphere(u3, u4));
    PdfSolidAngle pdf = 1 / (4 * kPi * units::steradian);
    Intensity intensity = light.intensity;
    if (light.profile) {  // uniform directions, weighted by the map
      intensity = light.intensity * intensity_factor(*light.profile, photon.direction);
      if (!(sg::max_component(intensity) > sg::zero)) return std::nullopt;
    }
    if (light.type == Light::Type::spot) {  // uniform directions, weighted by the cone's falloff
      Real falloff = spot_falloff(light.spot, sg::dot(light.spot.direction, photon.direction));
      if (!(falloff > 0)) return std::nullopt;
      intensity = light.intensity * falloff;
    }
    photon.flux = intensity / (pdf * probability);
    photon.pdf_direction = pdf;
    return photon;
  }
  if (light.type == Light::Type::environment || light.type == Light::Type::distant) {
    // Towards the scene along -ω, from a disc of the bounding sphere's radius
    // perpendicular to ω: the flux through it is E · πR², the environment's
    // E = L (head on, cos = 1) per unit of the solid angle ω was drawn from.
    std::optional<Environment::Sample> sky;
    if (light.type == Light::Type::environment) {
      sky = environment_->sample(u1, u2);
      if (!sky) return std::nullopt;
    }
    DirectionWorld towards_light = sky ? sky->wi : light.distant.direction;
    ShadingFrame disc = ShadingFrame::from_normal(sg::to_normal(towards_light));
    Real x, y;
    sample_concentric_disk(u3, u4, x, y);
    vector<Shading> across(x * scene_radius_, y * scene_radius_, scene_radius_);
    photon.origin = scene_center_ + disc.from_local(across);
    photon.origin_error = kernel::abs(to_kernel(photon.origin)) * kernel::gamma(4);
    photon.direction = -towards_light;
    quantity<dim::area> disc_area = kPi * scene_radius_ * scene_radius_;
    if (!sky) {
      photon.flux = light.distant.irradiance * disc_area / probability;
      return photon;
    }
    Proj head_on = Real(1) * units::proj;
    photon.flux = sky->radiance * head_on * disc_area / (sky->pdf * probability);
    return photon;
  }
  SurfacePoint point;
  sample_surface(index, time, chosen.u_within, u1, u2, point.position, point.position_error, point.normal,
                 point.pdf_area);
  NormalWorld normal = point.normal;
  Real sides = 1;
  if (light.two_sided) {  // either side, evenly
    sides = 2;
    if (u3 < Real(0.5)) {
      normal = -normal;
      u3 = 2 * u3;
    } else {
      u3 = 2 * u3 - 1;
    }
  }
  ShadingFrame frame = ShadingFrame::from_normal(normal);
  DirectionShading local = from_kernel<DirectionShading>(sample_cosine_hemisphere(std::min(u3, Real(0x1.fffffep-1f)), u4));
  Proj cos_emitted = sg::cos_theta(local);
  if (!(cos_emitted > sg::zero)) return std::nullopt;
  PdfSolidAngle pdf_direction = cos_emitted / (kPi * units::steradian * units::proj);
  photon.origin = point.position;
  photon.origin_error = point.position_error;
  photon.surface_normal = to_kernel(normal);
  photon.direction = frame.from_local(local);
  photon.flux = light.radiance * cos_emitted * sides / (pdf_direction * point.pdf_area * probability);
  photon.pdf_position = point.pdf_area;
  photon.pdf_direction = pdf_direction / sides;
  return photon;
}

EmissionDensity Lights::emission_density(uint32_t index, const SurfaceHit& point, DirectionWorld direction,
                                         Time time) const {
  const Light& light = lights_[index];
  EmissionDensity density;
  density.choice = light_probability(power_cdf_, index);
  if (light.type == Light::Type::point || light.type == Light::Type::spot) {
    density.direction = 1 / (4 * kPi * units::steradian);  // uniform, as sample_emission() draws them
    return density;
  }
  Proj cos_emitted = sg::dot(point.normal, direction);
  if (light.two_sided) cos_emitted = sg::abs(cos_emitted);
  if (!(cos_emitted > sg::zero)) return density;
  const Real sides = light.two_sided ? 2 : 1;
  density.position = light.motion < 0 ? light.pdf_area : moving_pdf_area(light, point, time);
  density.direction = cos_emitted / (sides * kPi * units::steradian * units::proj);
  return density;
}

bool Lights::has_directional_lights() const {
  return std::any_of(lights_.begin(), lights_.end(), [](const Light& light) {
    return light.type == Light::Type::environment || light.type == Light::Type::distant;
  });
}

PdfSolidAngle Lights::environment_pdf(PointWorld reference, DirectionWorld direction) const {
  return weight_of(environment_index_, reference) * environment_->pdf(direction);
}

// The density per world area at `time` with which sample_moving() draws `hit`.
PdfArea Lights::moving_pdf_area(const Light& light, const SurfaceHit& hit, Time time) const {
  const RigidMotion& motion = motions_[light.motion];
  if (light.type == Light::Type::sphere) {
    Length radius = placed_radius(motion.render_from_object(time), light.object_radius);
    return 1.0f / (4 * sg::pi * radius * radius);
  }
  return light.pdf_area / area_scale(motion.at(sg::raw(time)), to_kernel(hit.normal));
}

}  // namespace safegi::render
