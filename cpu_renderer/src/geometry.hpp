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

// A world-space ray; `time` picks the pose of moving objects.
struct Ray {
  Float3 origin;
  Float3 direction;  // unit length
  float time = 0.0f;
};

struct SurfaceHit {
  Float3 position;
  Float3 position_error;  // rounding-error box around `position`
  Float3 normal;          // unit geometric normal, on the side given by the winding
  float distance = 0.0f;  // along the ray
  uint32_t shape = 0;     // index into Scene::shapes
};

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

  std::optional<SurfaceHit> intersect(const Ray& ray, float t_max) const;
  bool occluded(const Ray& ray, float t_max) const;

 private:
  template <bool any_hit>
  bool trace(const Ray& ray, float& t_max, uint32_t& primitive, float& b1, float& b2) const;

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

  std::optional<SurfaceHit> intersect(const Ray& ray, float t_max = kernel::kInfinity) const;
  bool occluded(const Ray& ray, float t_max) const;
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

// Points a ray leaves from, pushed off the surface on the side of `direction`.
Ray spawn_ray(const SurfaceHit& hit, Float3 direction, float time);
// A shadow ray from a surface to a point; `t_max` stops just short of the target.
Ray spawn_ray_to(const SurfaceHit& from, Float3 target, Float3 target_error, Float3 target_normal, float time,
                 float& t_max);

}  // namespace safegi::render
