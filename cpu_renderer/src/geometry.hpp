// Render-time geometry: triangles and spheres under a BVH, static ones in
// world space, moving ones as instances in object space.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "bvh.hpp"
#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::render {

using kernel::Float3;

// A world-space ray at an instant of the shutter interval, which picks the pose
// of moving objects.
struct TimedRay : ray<World> {
  Time time = sg::zero;
};

struct SurfaceHit {
  PointWorld position;
  Float3 position_error;  // rounding-error box around `position`, in metres
  NormalWorld normal;     // geometric normal, on the side given by the winding
  Length distance = sg::zero;  // along the ray
  uint32_t shape = 0;     // index into Scene::shapes
};

namespace kernel {

// A ray in the kernel's plain floats: metres, seconds, a unit direction.
struct Ray {
  Float3 origin;
  Float3 direction;
  float time = 0.0f;
};

struct Hit {
  Float3 position;
  Float3 position_error;
  Float3 normal;
  float distance = 0.0f;
  uint32_t shape = 0;
};

// An affine map on plain floats (row-major 3x4), for instancing and motion.
struct Affine {
  float m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};

  static Affine from(const ObjectToWorld& map);
  Float3 apply_point(Float3 p) const {
    return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
            m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
            m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
  }
  Float3 apply_vector(Float3 v) const {
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

}  // namespace kernel

using kernel::Affine;

// Primitives of one space: triangles first, then spheres, under one BVH.
class PrimitiveSet {
 public:
  struct Triangle {
    Float3 p0, e1, e2;
    uint32_t shape;
  };
  struct Sphere {
    Float3 center;
    float radius;
    uint32_t shape;
  };

  void add_triangle(Float3 a, Float3 b, Float3 c, uint32_t shape) { triangles_.push_back({a, b - a, c - a, shape}); }
  void add_sphere(Float3 center, float radius, uint32_t shape) { spheres_.push_back({center, radius, shape}); }
  void build();

  bool empty() const { return triangles_.empty() && spheres_.empty(); }
  kernel::Bounds3 bounds() const { return bvh_.bounds(); }

  std::optional<kernel::Hit> intersect(const kernel::Ray& ray, float t_max) const;
  bool occluded(const kernel::Ray& ray, float t_max) const;

 private:
  template <bool any_hit>
  bool trace(const kernel::Ray& ray, float& t_max, uint32_t& primitive, float& b1, float& b2) const;

  std::vector<Triangle> triangles_;
  std::vector<Sphere> spheres_;
  kernel::Bvh bvh_;
};

// Rigid motion between two poses, interpolated as translation, rotation
// (quaternion slerp) and scale, like pbrt's AnimatedTransform.
class RigidMotion {
 public:
  RigidMotion(const Affine& at_open, const Affine& at_close, float time_open, float time_close);
  Affine at(float time) const;

 private:
  struct Pose {
    Float3 translation;
    float rotation[4];  // quaternion x, y, z, w
    float scale[3][3];
  };
  static Pose decompose(const Affine& m);
  Pose open_, close_;
  float time_open_, time_close_;
};

class Geometry {
 public:
  explicit Geometry(const Scene& scene);

  std::optional<SurfaceHit> intersect(const TimedRay& ray) const;
  bool occluded(const TimedRay& ray, Length t_max) const;
  bool has_motion() const { return !instances_.empty(); }
  kernel::Bounds3 bounds() const { return bounds_; }

 private:
  struct Instance {
    PrimitiveSet primitives;  // in object space
    RigidMotion motion;
    kernel::Bounds3 swept_bounds;  // world space, over the shutter interval
  };

  PrimitiveSet static_primitives_;  // in world space
  std::vector<Instance> instances_;
  kernel::Bounds3 bounds_;
};

// A ray leaving a surface, its origin pushed off the surface on the side of `direction`.
TimedRay spawn_ray(const SurfaceHit& hit, DirectionWorld direction, Time time);
// A shadow ray from a surface to a point (with its error box and normal, zero
// for point lights); `t_max` stops just short of the target.
TimedRay spawn_ray_to(const SurfaceHit& from, PointWorld target, Float3 target_error, Float3 target_normal, Time time,
                      Length& t_max);

}  // namespace safegi::render
