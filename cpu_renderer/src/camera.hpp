// Perspective camera: pinhole or thin lens, with a shutter interval. Lens and
// time samples are drawn only when the scene has an aperture or a shutter, so
// a feature the scene does not use costs nothing.
#pragma once

#include <algorithm>

#include "geometry.hpp"
#include "safegi/cpu_renderer/scene.hpp"
#include "sampler.hpp"
#include "safegi/cpu_renderer/sampling.hpp"

namespace safegi::render {

class PerspectiveCamera {
 public:
  PerspectiveCamera(const Camera& camera, int width, int height)
      : position_(camera.position),
        lens_radius_(camera.lens_radius),
        focus_distance_(camera.focus_distance),
        shutter_open_(camera.shutter_open),
        shutter_span_(camera.shutter_close - camera.shutter_open) {
    forward_ = sg::normalize(camera.look_at - camera.position);
    right_ = sg::normalize(sg::cross(forward_, camera.up));
    up_ = sg::normalize(sg::cross(right_, forward_));
    Real tangent = sg::tan(0.5f * camera.fov);
    Real shorter = static_cast<Real>(std::min(width, height));
    // Half-extents of the image plane at unit distance; the shorter axis spans the fov.
    half_width_ = tangent * static_cast<Real>(width) / shorter;
    half_height_ = tangent * static_cast<Real>(height) / shorter;
    inverse_width_ = 1.0f / static_cast<Real>(width);
    inverse_height_ = 1.0f / static_cast<Real>(height);
  }

  bool has_lens() const { return lens_radius_ > sg::zero; }
  bool has_shutter() const { return shutter_span_ > sg::zero; }

  TimedRay generate(int pixel_x, int pixel_y, Sampler& sampler) const {
    Sample2 film = sampler.next_2d();
    Real sx = (2 * (static_cast<Real>(pixel_x) + film.u) * inverse_width_ - 1) * half_width_;
    Real sy = (1 - 2 * (static_cast<Real>(pixel_y) + film.v) * inverse_height_) * half_height_;
    DirectionWorld direction = sg::normalize(forward_ * 1.0f + right_ * sx + up_ * sy);
    TimedRay ray{{position_, direction}, shutter_open_};
    if (has_lens()) {
      Sample2 lens = sampler.next_2d();
      Real lx, ly;
      sample_concentric_disk(lens.u, lens.v, lx, ly);
      PointWorld focus_point = position_ + direction * (focus_distance_ / sg::dot(direction, forward_));
      ray.o = position_ + right_ * (lx * lens_radius_) + up_ * (ly * lens_radius_);
      ray.d = sg::normalize(focus_point - ray.o);
    }
    if (has_shutter()) ray.time = shutter_open_ + sampler.next_1d() * shutter_span_;
    return ray;
  }

 private:
  PointWorld position_;
  DirectionWorld forward_, right_, up_;
  Length lens_radius_, focus_distance_;
  Time shutter_open_, shutter_span_;
  Real half_width_, half_height_, inverse_width_, inverse_height_;
};

}  // namespace safegi::render
