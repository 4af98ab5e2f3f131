// Rigid motion of objects over the shutter interval, on plain floats: shared
// by the CPU renderer (instances, moving emitters) and the GL preview, so both
// move objects alike.
#pragma once

#include <optional>

#include "safegi/cpu_renderer/kernel_math.hpp"
#include "safegi/cpu_renderer/scene.hpp"
#include "safegi/cpu_renderer/types.hpp"

namespace safegi::render {

namespace kernel {

// An affine map on plain floats (row-major 3x4), for instancing and motion.
struct Affine {
  Real m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};

  static Affine from(const RenderFromObject& map);
  Real3 apply_point(Real3 p) const {
    return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
            m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
            m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
  }
  Real3 apply_vector(Real3 v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
  }
  friend Affine operator*(const Affine& a, const Affine& b) {
    Affine r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j)
        r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j] + (j == 3 ? a.m[i][3] : 0.0f);
    return r;
  }
};

inline Real3 column(const Affine& m, int c) { return {m.m[0][c], m.m[1][c], m.m[2][c]}; }

Affine inverse(const Affine& a);

}  // namespace kernel

using kernel::Affine;
using kernel::Real3;

// Rigid motion between two poses, interpolated as translation, rotation
// (quaternion slerp) and scale, like pbrt's AnimatedTransform.
class RigidMotion {
 public:
  RigidMotion(const Affine& at_open, const Affine& at_close, Real time_open, Real time_close);
  Affine at(Real time) const;
  RenderFromObject render_from_object(Time time) const;

 private:
  struct Pose {
    Real3 translation;
    Real rotation[4];  // quaternion x, y, z, w
    Real scale[3][3];
  };
  static Pose decompose(const Affine& m);
  Pose open_, close_;
  Real time_open_, time_close_;
};

// How `shape` moves while the camera's shutter is open; nothing when it has no
// pose at shutter close or the shutter interval is empty.
std::optional<RigidMotion> motion_of(const Shape& shape, const Camera& camera);

// Area of a surface element after `m` per area before, given its normal after
// (|det L| / |Lᵀ n| for the linear part L).
Real area_scale(const Affine& m, Real3 normal_after);

}  // namespace safegi::render
