// The scene as the rasteriser sees it: every shape as triangles in object
// space (spheres tessellated), its pose at any shutter time, and the emitters
// as sets of point-like light samples.
#pragma once

#include <optional>
#include <vector>

#include "safegi/cpu_renderer/emitter_triangles.hpp"
#include "safegi/cpu_renderer/rigid_motion.hpp"  // both renderers move objects alike
#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::preview {

using namespace safegi::render;

struct DrawRange {
  int first = 0;
  int count = 0;
};

struct SceneMeshes {
  std::vector<PointObject> positions;  // non-indexed triangles, every shape after the other
  std::vector<normal<Object>> normals; // a mesh's vertex normals (else flat), smooth for spheres
  std::vector<DrawRange> ranges;       // one per Scene::shapes entry
};

// Spheres become `segments` × segments/2 quads: at 64 the silhouette lies within
// 0.12% of the radius of the true sphere the CPU renderer intersects.
SceneMeshes tessellate(const Scene& scene, int sphere_segments = 64);

// Where each shape is at a time within the shutter (the CPU renderer's
// interpolation of rigid motion: translation lerp, rotation slerp).
class ScenePoses {
 public:
  explicit ScenePoses(const Scene& scene);
  bool animated() const { return animated_; }
  bool moves(size_t shape) const { return motions_[shape].has_value(); }
  RenderFromObject at(size_t shape, Time time) const;
  // A sphere around everything the scene holds over the whole shutter.
  PointWorld bounds_center() const { return center_; }
  Length bounds_radius() const { return radius_; }

 private:
  const Scene& scene_;
  std::vector<std::optional<RigidMotion>> motions_;
  bool animated_ = false;
  PointWorld center_;
  Length radius_ = sg::zero;
};

struct EmitterPoint {
  PointWorld position;
  NormalWorld normal;
};

// A diffuse emitter (mesh or sphere) at its shutter-open pose, as the CPU
// renderer's Lights place it, sampled uniformly by area.
class Emitter {
 public:
  // At the shape's own pose, or at `render_from_object` (a moving emitter at one
  // shutter time: its area, and so each sample's share, follows its scale).
  Emitter(const Scene& scene, int shape);
  Emitter(const Scene& scene, int shape, const RenderFromObject& render_from_object);
  int shape() const { return shape_; }
  Radiance radiance() const { return radiance_; }
  bool two_sided() const { return two_sided_; }
  quantity<dim::area> area() const { return area_; }
  EmitterPoint sample(float u1, float u2) const;

 private:
  int shape_;
  Radiance radiance_;
  bool two_sided_;
  bool sphere_ = false;
  PointWorld center_;
  Length radius_ = sg::zero;
  std::vector<EmitterTriangle<World>> triangles_;
  quantity<dim::area> area_ = sg::zero;
};

std::vector<Emitter> emitters_of(const Scene& scene);

// A flat shape's plane in object space: a point on it and its unit normal
// (the winding's). nullopt for a sphere, a degenerate mesh, or a mesh whose
// vertices leave the plane by more than 1e-5 of its size: a curved mirror,
// which the preview cannot reflect with one planar reflection pass.
struct Plane {
  PointObject point;
  normal<Object> unit_normal;
};
std::optional<Plane> plane_of(const Shape& shape);

// The i-th point of the R2 low-discrepancy sequence in [0,1)²: consecutive
// runs of any length cover the square evenly, so pass p can take points
// p·N … p·N+N−1 and all passes together stay well spread.
void r2_point(uint32_t index, float& u, float& v);

}  // namespace safegi::preview
