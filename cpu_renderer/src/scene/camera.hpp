// The camera's rays: perspective (pinhole or thin lens), orthographic (parallel
// rays from an image-sized window, thin lens too) or environment (every
// direction, longitude across the image, latitude down it), with a shutter
// interval. Lens and time samples are drawn only when the scene has an
// aperture or a shutter, so a feature the scene does not use costs nothing.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "accel/geometry.hpp"
#include "safegi/cpu_renderer/scene.hpp"
#include "integrators/sampler.hpp"
#include "safegi/cpu_renderer/sampling.hpp"

namespace safegi::render {

// A camera ray's cone, the textures' footprint: its width at the camera and how
// fast it widens (the angle one pixel subtends at the image centre), narrowed
// by 1/√spp as pbrt-v3 narrows its rays' differentials (ScaleDifferentials):
// the more samples share a pixel, the less each one needs to filter, and the
// same scene converges to the same image in both renderers.
// Past a specular surface the cone goes on bent as paraxial optics bends a
// beam (pbrt-v3 follows its rays' differentials there): a convex mirror
// spreads it, a glass ball focuses it, so a texture seen through one is
// filtered over the footprint the lens makes, not the camera's.
struct PixelCone {
  Length width = sg::zero;  // signed: negative past a focus
  Angle spread = sg::zero;  // negative while converging

  // The cone `distance` further on.
  PixelCone after(Length distance) const { return {width + distance * (spread / units::radian), spread}; }
  // Reflected by a mirror with radius of curvature `radius`, positive where it
  // bulges towards the incoming ray (none: flat): a convex one spreads the
  // cone by twice the normal's turn across it, w/r.
  PixelCone reflected(std::optional<Length> radius) const {
    return radius ? PixelCone{width, spread + 2 * (width / *radius) * units::radian} : *this;
  }
  // Refracted into a medium `eta` times as dense: Snell's law (angles over η)
  // and the surface's power (η − 1)/(η r) on a beam `width` wide.
  PixelCone refracted(Real eta, std::optional<Length> radius) const {
    PixelCone bent{width, spread / eta};
    if (radius) bent.spread = bent.spread - (width / *radius) * (1 - 1 / eta) * units::radian;
    return bent;
  }
};

inline PixelCone pixel_cone(const Camera& camera, int width, int height, int samples_per_pixel) {
  const Real narrowing = 1 / std::sqrt(static_cast<Real>(std::max(samples_per_pixel, 1)));
  const Real shorter = static_cast<Real>(std::min(width, height));
  switch (camera.projection) {
    case CameraProjection::orthographic:
      return {narrowing * camera.view_size / shorter, sg::zero};
    case CameraProjection::environment: {
      const Real pi = std::numbers::pi_v<Real>;
      return {sg::zero,
              narrowing * std::max(2 * pi / static_cast<Real>(width), pi / static_cast<Real>(height)) * units::radian};
    }
    case CameraProjection::perspective:
      break;
  }
  return {sg::zero, narrowing * 2 * sg::tan(0.5f * camera.fov) / shorter * units::radian};
}

class CameraRays {
 public:
  CameraRays(const Camera& camera, int width, int height)
      : projection_(camera.projection),
        position_(camera.position),
        lens_radius_(camera.lens_radius),
        focus_distance_(camera.focus_distance),
        shutter_open_(camera.shutter_open),
        shutter_span_(camera.shutter_close - camera.shutter_open) {
    forward_ = sg::normalize(camera.look_at - camera.position);
    right_ = sg::normalize(sg::cross(forward_, camera.up));
    up_ = sg::normalize(sg::cross(right_, forward_));
    const Real shorter = static_cast<Real>(std::min(width, height));
    // The image's half-extents: on the image plane at unit distance (the
    // shorter axis spans the fov), or where the shorter one is 1 (orthographic).
    const Real tangent = camera.projection == CameraProjection::perspective ? sg::tan(0.5f * camera.fov) : Real(1);
    half_width_ = tangent * static_cast<Real>(width) / shorter;
    half_height_ = tangent * static_cast<Real>(height) / shorter;
    half_view_ = 0.5f * camera.view_size;
    inverse_width_ = 1.0f / static_cast<Real>(width);
    inverse_height_ = 1.0f / static_cast<Real>(height);
  }

  bool has_lens() const { return lens_radius_ > sg::zero && projection_ != CameraProjection::environment; }

  // The image's x and y pixel steps seen along a camera ray of direction `d`,
  // relative to the pixel cone's (ConeFootprint::step_x, step_y): pbrt-v3's
  // differentials' directions and lengths. Perspective: the image plane's
  // axes off the ray, shrunk by d·forward (a pixel at the corner of a wide
  // image subtends less); orthographic: the axes themselves; environment: none
  // (the cone's circle).
  std::pair<ConeStep, ConeStep> pixel_steps(DirectionWorld d) const {
    if (projection_ == CameraProjection::environment) return {};
    const sg::vec3_rep right = sg::raw(right_), up = sg::raw(up_);
    if (projection_ == CameraProjection::orthographic) return {sg::from_raw<ConeStep>(right), sg::from_raw<ConeStep>(up)};
    const sg::vec3_rep along = sg::raw(d);
    const Real facing = glm::dot(along, sg::raw(forward_));
    auto off_ray = [&](sg::vec3_rep axis) { return sg::from_raw<ConeStep>((axis - along * glm::dot(along, axis)) * facing); };
    return {off_ray(right), off_ray(up)};
  }
  bool has_shutter() const { return shutter_span_ > sg::zero; }

  // Light tracing (the bidirectional path tracer's t = 1 strategy) sees the
  // camera as a pinhole: its position, and for a direction leaving it, where
  // on the image (in pixels from the top left corner) that direction's rays
  // start, with the density over solid angle of generate_at()'s directions
  // for a film point uniform over the whole image, 1 / (A cos³ θ), A the
  // image's area on the plane at unit distance (pbrt-v3's We over the
  // pinhole's unit "lens area", one cosine of which the caller's inverse-
  // square law per projected area holds). None outside the image.
  bool is_pinhole() const { return projection_ == CameraProjection::perspective && !has_lens(); }
  PointWorld position() const { return position_; }
  struct ImagePoint {
    Real x = 0, y = 0;
    PdfSolidAngle pdf = sg::zero;
  };
  std::optional<ImagePoint> image_point(DirectionWorld d) const {
    const Real facing = sg::dot(d, forward_);
    if (!(facing > 0)) return std::nullopt;
    const Real sx = sg::dot(d, right_) / facing;
    const Real sy = sg::dot(d, up_) / facing;
    const Real fx = (sx / half_width_ + 1) / 2, fy = (1 - sy / half_height_) / 2;
    if (!(fx >= 0 && fx < 1 && fy >= 0 && fy < 1)) return std::nullopt;
    return ImagePoint{fx / inverse_width_, fy / inverse_height_, direction_pdf(d)};
  }
  PdfSolidAngle direction_pdf(DirectionWorld d) const {
    const Real facing = sg::dot(d, forward_);
    if (!(facing > 0)) return sg::zero;
    const Real image_area = 4 * half_width_ * half_height_;
    return 1 / (image_area * facing * facing * facing * units::steradian);
  }

  // A ray through the image point (x, y), in pixels from the top left corner.
  TimedRay generate_at(Real x, Real y, Sampler& sampler) const {
    const Real fx = x * inverse_width_;
    const Real fy = y * inverse_height_;
    TimedRay ray{{position_, forward_}, shutter_open_};
    if (projection_ == CameraProjection::environment) {
      ray.d = around(fx, fy);
    } else {
      const Real sx = (2 * fx - 1) * half_width_, sy = (1 - 2 * fy) * half_height_;
      if (projection_ == CameraProjection::orthographic)
        ray.o = position_ + right_ * (sx * half_view_) + up_ * (sy * half_view_);
      else
        ray.d = sg::normalize(forward_ * 1.0f + right_ * sx + up_ * sy);
      if (has_lens()) focus_through_lens(ray, sampler.next_2d());
    }
    if (has_shutter()) ray.time = shutter_open_ + sampler.next_1d() * shutter_span_;
    return ray;
  }

 private:
  // pbrt-v3's EnvironmentCamera: θ from the top of the image, φ across it.
  DirectionWorld around(Real fx, Real fy) const {
    const Real pi = std::numbers::pi_v<Real>;
    const Real theta = pi * fy, phi = 2 * pi * fx;
    const Real sin_theta = std::sin(theta);
    return sg::normalize(right_ * (sin_theta * std::cos(phi)) + up_ * std::cos(theta) +
                         forward_ * (sin_theta * std::sin(phi)));
  }

  // The thin lens: the ray leaves a point of the lens (the disk around its
  // pinhole ray's origin) for where that ray meets the plane of focus.
  void focus_through_lens(ray<World>& ray, Sample2 lens) const {
    Real lx, ly;
    sample_concentric_disk(lens.u, lens.v, lx, ly);
    const PointWorld focus_point = ray.o + ray.d * (focus_distance_ / sg::dot(ray.d, forward_));
    ray.o = ray.o + right_ * (lx * lens_radius_) + up_ * (ly * lens_radius_);
    ray.d = sg::normalize(focus_point - ray.o);
  }

  CameraProjection projection_;
  PointWorld position_;
  DirectionWorld forward_, right_, up_;
  Length lens_radius_, focus_distance_, half_view_;
  Time shutter_open_, shutter_span_;
  Real half_width_, half_height_, inverse_width_, inverse_height_;
};

}  // namespace safegi::render
