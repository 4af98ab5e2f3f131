// Render-time geometry: triangles and spheres under a BVH, static ones in
// world space, moving ones as instances in object space.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "accel/bvh.hpp"
#include "accel/triangle_block.hpp"
#include "safegi/cpu_renderer/rigid_motion.hpp"
#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::render {

using kernel::Real3;

// A world-space ray at an instant of the shutter interval, which picks the pose
// of moving objects.
struct TimedRay : ray<World> {
  Time time = sg::zero;
};

// A step across a ray's cone of neighbouring rays, relative to the cone's width.
using ConeStep = vector<World, dim::dimensionless>;

struct SurfaceHit {
  PointWorld position;
  Real3 position_error;  // rounding-error box around `position`, in metres
  NormalWorld normal;     // geometric normal, on the side given by the winding
  Length distance = sg::zero;  // along the ray
  uint32_t shape = 0;     // index into Scene::shapes
  // The triangle hit (its first index is 3·face into Shape::indices); unused
  // for spheres.
  uint32_t face = 0;
};

namespace kernel {

// A ray in the kernel's plain floats: metres, seconds, a unit direction.
struct Ray {
  Real3 origin;
  Real3 direction;
  Real time = 0.0f;
};

// A primitive by its shape and its index within the shape.
struct PrimitiveId {
  uint32_t shape = 0;
  uint32_t face = 0;
};

struct Hit {
  Real3 position;
  Real3 position_error;
  Real3 normal;
  Real distance = 0.0f;
  uint32_t shape = 0;
  uint32_t face = 0;
};

}  // namespace kernel

// Primitives of one space, triangles and spheres each under a BVH of their
// own; a leaf's triangles are tested four at a time (triangle_block.hpp).
class PrimitiveSet {
 public:
  struct Triangle {  // as added, until build() packs it into its leaf's block
    Real3 p0, e1, e2;
    uint32_t shape;
    uint32_t face;  // its index within its shape: hits carry it for texture lookups
  };
  struct Sphere {
    Real3 center;
    Real radius;
    uint32_t shape;
  };

  void add_triangle(Real3 a, Real3 b, Real3 c, uint32_t shape, uint32_t face) {
    triangles_.push_back({a, b - a, c - a, shape, face});
  }
  void add_sphere(Real3 center, Real radius, uint32_t shape) { spheres_.push_back({center, radius, shape}); }
  // Builds the hierarchies on up to `threads` threads (the result does not depend on the count).
  void build(int threads = 1);

  bool empty() const { return triangle_blocks_.empty() && spheres_.empty(); }
  kernel::Bounds3 bounds() const;
  // Bytes held for tracing: triangle blocks, spheres, hierarchies.
  size_t memory_bytes() const;

  // The nearest hit before t_max but on the `skipped` triangles (alpha-masked
  // ones the ray has passed).
  std::optional<kernel::Hit> intersect(const kernel::Ray& ray, Real t_max,
                                       std::span<const kernel::PrimitiveId> skipped = {}) const;
  bool occluded(const kernel::Ray& ray, Real t_max) const;

 private:
  struct Found;  // the primitive a trace hit
  void build_triangles(int threads);
  void build_spheres(int threads);
  template <bool any_hit>
  bool trace(const kernel::Ray& ray, Real& t_max, Found& found, std::span<const kernel::PrimitiveId> skipped = {}) const;
  template <bool any_hit, bool skipping>
  bool trace_triangles(const kernel::Ray& ray, const kernel::TraversalRay& traversal, Real& t_max, Found& found,
                       std::span<const kernel::PrimitiveId> skipped) const;
  template <bool any_hit>
  bool trace_spheres(const kernel::Ray& ray, const kernel::TraversalRay& traversal, Real& t_max,
                     Found& found) const;

  std::vector<Triangle> triangles_;  // emptied by build()
  // Each triangle leaf's triangles, from a block boundary on (the leaf names its first block).
  std::vector<kernel::TriangleBlock> triangle_blocks_;
  std::vector<Sphere> spheres_;  // in the order of the sphere hierarchy's leaf entries
  kernel::Bvh8 triangle_bvh_;
  kernel::Bvh sphere_bvh_;
};

class SurfaceTextures;

class Geometry {
 public:
  // Builds the hierarchies on up to `threads` threads. The scene must outlive
  // the Geometry when a shape has an alpha mask (the masks are read at hits).
  explicit Geometry(const Scene& scene, int threads = 1);

  // The nearest surface; with alpha masks, the nearest where none is 0.
  std::optional<SurfaceHit> intersect(const TimedRay& ray) const;
  bool occluded(const TimedRay& ray, Length t_max) const;
  bool has_motion() const { return !instances_.empty(); }
  kernel::Bounds3 bounds() const { return bounds_; }

 private:
  std::optional<SurfaceHit> nearest(const TimedRay& ray, std::span<const kernel::PrimitiveId> skipped = {}) const;
  bool any_hit(const TimedRay& ray, Length t_max) const;
  // pbrt-v3 tests the masks inside its triangles' intersection; here the ray
  // is traced again with each masked triangle it met skipped, so that a
  // surface in the masked one's plane still shows through its holes.
  std::optional<SurfaceHit> nearest_unmasked(const TimedRay& ray, Length t_max, bool shadow) const;
  bool masked(const SurfaceHit& hit, Time time, bool shadow) const;

  struct Instance {
    PrimitiveSet primitives;  // in object space
    RigidMotion motion;
    kernel::Bounds3 swept_bounds;  // world space, over the shutter interval
  };

  PrimitiveSet static_primitives_;  // in world space
  std::vector<Instance> instances_;
  kernel::Bounds3 bounds_;
  // Only when a shape has an alpha mask: the scene's shapes and their textures.
  const std::vector<Shape>* masked_shapes_ = nullptr;
  std::shared_ptr<const SurfaceTextures> mask_textures_;
};

// A ray leaving a surface, its origin pushed off the surface on the side of `direction`.
TimedRay spawn_ray(const SurfaceHit& hit, DirectionWorld direction, Time time);
// A shadow ray from a surface to a point (with its error box and normal, zero
// for point lights); `t_max` stops just short of the target.
TimedRay spawn_ray_to(const SurfaceHit& from, PointWorld target, Real3 target_error, Real3 target_normal, Time time,
                      Length& t_max);

}  // namespace safegi::render
