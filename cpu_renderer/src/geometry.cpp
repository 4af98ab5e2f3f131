#include "geometry.hpp"

#include "surface_texture.hpp"

#include <cmath>
#include <type_traits>

namespace safegi::render {

using kernel::abs;
using kernel::column;
using kernel::Bounds3;
using kernel::cross;
using kernel::dot;
using kernel::gamma;
using kernel::inverse;

namespace {

using kernel::Ray;

// Normals transform with the inverse transpose.
Real3 apply_normal(const Affine& inverse_map, Real3 n) {
  const auto& m = inverse_map.m;
  return kernel::normalize({m[0][0] * n.x + m[1][0] * n.y + m[2][0] * n.z, m[0][1] * n.x + m[1][1] * n.y + m[2][1] * n.z,
                            m[0][2] * n.x + m[1][2] * n.y + m[2][2] * n.z});
}

Real3 abs_apply_vector(const Affine& a, Real3 v) {
  Real3 r;
  for (int i = 0; i < 3; ++i) r[i] = std::fabs(a.m[i][0]) * v.x + std::fabs(a.m[i][1]) * v.y + std::fabs(a.m[i][2]) * v.z;
  return r;
}

Bounds3 transform_bounds(const Affine& m, const Bounds3& b) {
  Bounds3 result;
  for (int corner = 0; corner < 8; ++corner)
    result.extend(m.apply_point({corner & 1 ? b.upper.x : b.lower.x, corner & 2 ? b.upper.y : b.lower.y,
                                 corner & 4 ? b.upper.z : b.lower.z}));
  return result;
}

// The triangle test's arithmetic (see PrimitiveSet::trace).
struct Double3 {
  double x, y, z;
  friend Double3 operator-(Double3 a, Double3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
};
Double3 to_double(Real3 v) { return {v.x, v.y, v.z}; }
double dot(Double3 a, Double3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Double3 cross(Double3 a, Double3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

}  // namespace

// ---------------------------------------------------------------------------
// PrimitiveSet

void PrimitiveSet::build(int threads) {
  build_hierarchy(threads);
  move_into_traversal_order(threads);
}

void PrimitiveSet::build_hierarchy(int threads) {
  const uint32_t triangle_count = static_cast<uint32_t>(triangles_.size());
  auto bounds_of = [&](uint32_t i) {
    Bounds3 b;
    if (i < triangle_count) {
      const Triangle& t = triangles_[i];
      b.extend(t.p0);
      b.extend(t.p0 + t.e1);
      b.extend(t.p0 + t.e2);
    } else {
      const Sphere& s = spheres_[i - triangle_count];
      b.extend(s.center - Real3{s.radius, s.radius, s.radius});
      b.extend(s.center + Real3{s.radius, s.radius, s.radius});
    }
    return b;
  };
  bvh_ = kernel::Bvh(triangle_count + static_cast<uint32_t>(spheres_.size()), bounds_of,
                     kernel::Bvh::kDefaultMaxLeafSize, threads);
}

// Stores the primitives in the order the BVH's leaves name them, so that a
// leaf's triangles are adjacent in memory. A set of one kind then needs no map
// from leaf entries to primitives; a mixed one keeps it (triangles first).
void PrimitiveSet::move_into_traversal_order(int threads) {
  const std::vector<uint32_t> order = bvh_.take_primitive_order();
  const uint32_t count = static_cast<uint32_t>(order.size());
  if (triangles_.empty() || spheres_.empty()) {
    const int chunks = count >= kernel::kParallelMinimum ? threads : 1;
    auto gather = [&](auto& items) {
      std::remove_reference_t<decltype(items)> moved(items.size());
      kernel::for_each_chunk(count, chunks, [&](int, uint32_t begin, uint32_t end) {
        for (uint32_t k = begin; k < end; ++k) moved[k] = items[order[k]];
      });
      items = std::move(moved);
    };
    if (spheres_.empty()) {
      gather(triangles_);
      if (record_faces_) gather(faces_);
    } else {
      gather(spheres_);
    }
    return;
  }
  const uint32_t triangle_count = static_cast<uint32_t>(triangles_.size());
  std::vector<Triangle> triangles;
  std::vector<Sphere> spheres;
  std::vector<uint32_t> faces;
  triangles.reserve(triangles_.size());
  spheres.reserve(spheres_.size());
  faces.reserve(faces_.size());
  entry_primitive_.resize(count);
  for (uint32_t k = 0; k < count; ++k) {
    const uint32_t primitive = order[k];
    if (primitive < triangle_count) {
      entry_primitive_[k] = static_cast<uint32_t>(triangles.size());
      triangles.push_back(triangles_[primitive]);
      if (record_faces_) faces.push_back(faces_[primitive]);
    } else {
      entry_primitive_[k] = triangle_count + static_cast<uint32_t>(spheres.size());
      spheres.push_back(spheres_[primitive - triangle_count]);
    }
  }
  triangles_ = std::move(triangles);
  spheres_ = std::move(spheres);
  faces_ = std::move(faces);
}

size_t PrimitiveSet::memory_bytes() const {
  return triangles_.capacity() * sizeof(Triangle) + spheres_.capacity() * sizeof(Sphere) +
         (faces_.capacity() + entry_primitive_.capacity()) * sizeof(uint32_t) + bvh_.memory_bytes();
}

template <bool any_hit>
bool PrimitiveSet::trace(const Ray& ray, Real& t_max, uint32_t& primitive, Real& b1, Real& b2) const {
  kernel::TraversalRay traversal(ray.origin, ray.direction);
  const uint32_t triangle_count = static_cast<uint32_t>(triangles_.size());
  return bvh_.traverse<any_hit>(traversal, t_max, [&](uint32_t entry, Real& t_limit) {
    const uint32_t index = entry_primitive_.empty() ? entry : entry_primitive_[entry];
    if (index < triangle_count) {
      // Möller–Trumbore in double: in float its u, v and t carry an absolute
      // error that grows with |origin - p0| and the edge lengths, which opens
      // metre-wide cracks along the shared edges of 1e7 m triangles. The data
      // stays float; the double arithmetic costs ~5% of rays/s (docs/stability.md).
      const Triangle& tri = triangles_[index];
      const Double3 d = to_double(ray.direction), e1 = to_double(tri.e1), e2 = to_double(tri.e2);
      Double3 p = cross(d, e2);
      double det = dot(e1, p);
      if (det == 0.0) return false;
      double inverse_det = 1.0 / det;
      Double3 s = to_double(ray.origin) - to_double(tri.p0);
      double u = dot(s, p) * inverse_det;
      if (u < 0.0 || u > 1.0) return false;
      Double3 q = cross(s, e1);
      double v = dot(d, q) * inverse_det;
      if (v < 0.0 || u + v > 1.0) return false;
      Real t = static_cast<Real>(dot(e2, q) * inverse_det);
      if (!(t > 0.0f && t < t_limit)) return false;
      t_limit = t;
      primitive = index;
      b1 = static_cast<Real>(u);
      b2 = static_cast<Real>(v);
      return true;
    }
    // Sphere, with the discriminant computed from the perpendicular offset for
    // precision far from the sphere (Ray Tracing Gems, ch. 7).
    const Sphere& sphere = spheres_[index - triangle_count];
    Real3 oc = ray.origin - sphere.center;
    Real b = dot(oc, ray.direction);
    Real3 perpendicular = oc - ray.direction * b;
    Real r2 = sphere.radius * sphere.radius;
    Real discriminant = r2 - dot(perpendicular, perpendicular);
    if (discriminant < 0.0f) return false;
    Real c = dot(oc, oc) - r2;
    Real q = -b - std::copysign(std::sqrt(discriminant), b);
    Real t_near = c / q, t_far = q;
    if (t_near > t_far) std::swap(t_near, t_far);
    // Outside (c > 0) only the near root is a first hit; inside only the far one.
    Real t = c > 0.0f ? t_near : t_far;
    if (!(t > 0.0f && t < t_limit)) return false;
    t_limit = t;
    primitive = index;
    return true;
  });
}

std::optional<kernel::Hit> PrimitiveSet::intersect(const Ray& ray, Real t_max) const {
  uint32_t primitive = 0;
  Real b1 = 0, b2 = 0;
  if (!trace<false>(ray, t_max, primitive, b1, b2)) return std::nullopt;
  kernel::Hit hit;
  hit.distance = t_max;
  if (primitive < triangles_.size()) {
    const Triangle& tri = triangles_[primitive];
    // Möller–Trumbore's barycentrics (and t) carry an absolute error that grows
    // with |origin - p0| and the edge lengths: on a 2e7 m floor the hit lands
    // ~1 m off and its error box spans metres. The hit is recomputed on the
    // triangle's plane in double, so its error is that of rounding the point
    // itself to float, whatever the triangle's size.
    const Double3 o = to_double(ray.origin), d = to_double(ray.direction), p0 = to_double(tri.p0);
    const Double3 n = cross(to_double(tri.e1), to_double(tri.e2));
    double t = dot(p0 - o, n) / dot(d, n);
    if (std::isfinite(t) && t > 0) {
      hit.position = {static_cast<Real>(o.x + t * d.x), static_cast<Real>(o.y + t * d.y),
                      static_cast<Real>(o.z + t * d.z)};
      // Rounding to float, plus the double computation's own error (its t is
      // off by ~1e-16 |p0 - o| / |cos|, which moves the point along the ray:
      // off the plane by ~1e-16 (|o| + |p0| + |t d|)). The next ray's triangle
      // test is double too, so this box alone keeps it off this triangle; the
      // old barycentric box pushed rays metres off tilted 1e7 m triangles.
      constexpr double kDoubleError = 16 * 0x1p-53;
      Real3 computation_error = {
          static_cast<Real>(kDoubleError * (std::fabs(o.x) + std::fabs(p0.x) + std::fabs(t * d.x))),
          static_cast<Real>(kDoubleError * (std::fabs(o.y) + std::fabs(p0.y) + std::fabs(t * d.y))),
          static_cast<Real>(kDoubleError * (std::fabs(o.z) + std::fabs(p0.z) + std::fabs(t * d.z)))};
      hit.position_error = abs(hit.position) * gamma(2) + computation_error;
    } else {  // Möller–Trumbore accepted a hit the plane test cannot place: keep its own point
      Real3 along_u = tri.e1 * b1, along_v = tri.e2 * b2;
      hit.position = tri.p0 + along_u + along_v;
      hit.position_error = (abs(tri.p0) + abs(along_u) + abs(along_v)) * gamma(7);
    }
    hit.normal = kernel::normalize(cross(tri.e1, tri.e2));
    hit.shape = tri.shape;
    if (record_faces_) hit.face = faces_[primitive];
  } else {
    const Sphere& sphere = spheres_[primitive - triangles_.size()];
    Real3 relative = ray.origin + ray.direction * t_max - sphere.center;
    relative = relative * (sphere.radius / kernel::length(relative));  // reproject onto the surface
    hit.position = sphere.center + relative;
    hit.position_error = (abs(relative) + abs(sphere.center)) * gamma(6);
    hit.normal = relative * (1.0f / sphere.radius);
    hit.shape = sphere.shape;
  }
  return hit;
}

bool PrimitiveSet::occluded(const Ray& ray, Real t_max) const {
  uint32_t primitive = 0;
  Real b1 = 0, b2 = 0;
  return trace<true>(ray, t_max, primitive, b1, b2);
}

// ---------------------------------------------------------------------------
// Geometry

namespace {

Real uniform_scale(const Affine& m) { return kernel::length(column(m, 0)); }

// Adds a shape in world space (`render_from_object` given) or in its own object space.
void add_shape(PrimitiveSet& set, const Shape& shape, uint32_t index, const RenderFromObject* render_from_object) {
  auto place = [&](PointObject p) { return render_from_object ? to_kernel((*render_from_object)(p)) : to_kernel(p); };
  if (shape.type == Shape::Type::sphere) {
    Real scale = render_from_object ? uniform_scale(Affine::from(*render_from_object)) : 1.0f;
    set.add_sphere(place(shape.center), sg::raw(shape.radius) * scale, index);
    return;
  }
  for (size_t i = 0; i + 2 < shape.indices.size(); i += 3)
    set.add_triangle(place(shape.positions[shape.indices[i]]), place(shape.positions[shape.indices[i + 1]]),
                     place(shape.positions[shape.indices[i + 2]]), index, static_cast<uint32_t>(i / 3));
}

}  // namespace

Geometry::Geometry(const Scene& scene, int threads) {
  Real time_open = sg::raw(scene.camera.shutter_open), time_close = sg::raw(scene.camera.shutter_close);
  const bool textured = scene.textured();
  if (textured) static_primitives_.record_faces();
  for (uint32_t i = 0; i < scene.shapes.size(); ++i) {
    const Shape& shape = scene.shapes[i];
    if (std::optional<RigidMotion> motion = motion_of(shape, scene.camera)) {
      Instance instance{PrimitiveSet{}, *motion, Bounds3{}};
      if (textured) instance.primitives.record_faces();
      add_shape(instance.primitives, shape, i, nullptr);
      instance.primitives.build(threads);
      constexpr int kPoseSamples = 64;  // bounds of the poses along the motion, padded below
      for (int s = 0; s <= kPoseSamples; ++s) {
        Real time = time_open + (time_close - time_open) * static_cast<Real>(s) / kPoseSamples;
        instance.swept_bounds.extend(transform_bounds(instance.motion.at(time), instance.primitives.bounds()));
      }
      Real3 pad = instance.swept_bounds.extent() * 0.01f;
      instance.swept_bounds.lower = instance.swept_bounds.lower - pad;
      instance.swept_bounds.upper = instance.swept_bounds.upper + pad;
      bounds_.extend(instance.swept_bounds);
      instances_.push_back(std::move(instance));
    } else {
      add_shape(static_primitives_, shape, i, &shape.render_from_object);
    }
  }
  static_primitives_.build(threads);
  if (!static_primitives_.empty()) bounds_.extend(static_primitives_.bounds());
  for (const Shape& shape : scene.shapes)
    if (shape.alpha || shape.shadow_alpha) {
      masked_shapes_ = &scene.shapes;
      mask_textures_ = std::make_shared<const SurfaceTextures>(scene);
      break;
    }
}

std::optional<SurfaceHit> Geometry::intersect(const TimedRay& ray) const {
  return mask_textures_ ? nearest_unmasked(ray, sg::from_raw<Length>(kernel::kInfinity), false) : nearest(ray);
}

bool Geometry::occluded(const TimedRay& ray, Length t_max) const {
  return mask_textures_ ? nearest_unmasked(ray, t_max, true).has_value() : any_hit(ray, t_max);
}

bool Geometry::masked(const SurfaceHit& hit, Time time, bool shadow) const {
  const Shape& shape = (*masked_shapes_)[hit.shape];
  auto zero_at_hit = [&](const std::optional<TexturedReflectance>& mask) {
    return mask && sg::raw(mask_textures_->reflectance_at(*mask, hit, sg::zero, time)).x == 0;
  };
  return zero_at_hit(shape.alpha) || (shadow && zero_at_hit(shape.shadow_alpha));
}

std::optional<SurfaceHit> Geometry::nearest_unmasked(const TimedRay& ray, Length t_max, bool shadow) const {
  // A bound on the layers one ray passes (foliage has tens); beyond it the
  // last hit counts as opaque, so that no ray can loop.
  constexpr int kMaxMaskedLayers = 4096;
  TimedRay beyond = ray;
  for (int layer = 0; layer < kMaxMaskedLayers; ++layer) {
    std::optional<SurfaceHit> hit = nearest(beyond);
    if (!hit) return std::nullopt;
    // Distances along the original ray, from its origin.
    if (layer > 0) hit->distance = sg::dot(hit->position - ray.o, ray.d);
    if (hit->distance >= t_max) return std::nullopt;
    if (!masked(*hit, ray.time, shadow) || layer + 1 == kMaxMaskedLayers) return hit;
    beyond = spawn_ray(*hit, ray.d, ray.time);
  }
  return std::nullopt;
}

std::optional<SurfaceHit> Geometry::nearest(const TimedRay& typed_ray) const {
  Ray ray{to_kernel(typed_ray.o), to_kernel(typed_ray.d), sg::raw(typed_ray.time)};
  Real t_max = kernel::kInfinity;
  std::optional<kernel::Hit> hit = static_primitives_.intersect(ray, t_max);
  if (hit) t_max = hit->distance;
  for (const Instance& instance : instances_) {
    if (!kernel::intersect_bounds(instance.swept_bounds, kernel::TraversalRay(ray.origin, ray.direction), t_max))
      continue;
    Affine render_from_object = instance.motion.at(ray.time);
    Affine object_from_render = inverse(render_from_object);
    Real3 direction = object_from_render.apply_vector(ray.direction);
    Real stretch = kernel::length(direction);
    Ray local{object_from_render.apply_point(ray.origin), direction * (1.0f / stretch), ray.time};
    std::optional<kernel::Hit> local_hit = instance.primitives.intersect(local, t_max * stretch);
    if (!local_hit) continue;
    kernel::Hit world = *local_hit;
    world.distance = local_hit->distance / stretch;
    world.position = render_from_object.apply_point(local_hit->position);
    world.position_error = abs_apply_vector(render_from_object, local_hit->position_error) +
                           (abs_apply_vector(render_from_object, abs(local_hit->position)) +
                            abs(column(render_from_object, 3))) * gamma(3);
    world.normal = apply_normal(object_from_render, local_hit->normal);
    t_max = world.distance;
    hit = world;
  }
  if (!hit) return std::nullopt;
  return SurfaceHit{from_kernel<PointWorld>(hit->position), hit->position_error, from_kernel<NormalWorld>(hit->normal),
                    sg::from_raw<Length>(hit->distance), hit->shape, hit->face};
}

bool Geometry::any_hit(const TimedRay& typed_ray, Length typed_t_max) const {
  Ray ray{to_kernel(typed_ray.o), to_kernel(typed_ray.d), sg::raw(typed_ray.time)};
  Real t_max = sg::raw(typed_t_max);
  if (static_primitives_.occluded(ray, t_max)) return true;
  for (const Instance& instance : instances_) {
    if (!kernel::intersect_bounds(instance.swept_bounds, kernel::TraversalRay(ray.origin, ray.direction), t_max))
      continue;
    Affine object_from_render = inverse(instance.motion.at(ray.time));
    Real3 direction = object_from_render.apply_vector(ray.direction);
    Real stretch = kernel::length(direction);
    Ray local{object_from_render.apply_point(ray.origin), direction * (1.0f / stretch), ray.time};
    if (instance.primitives.occluded(local, t_max * stretch)) return true;
  }
  return false;
}

// ---------------------------------------------------------------------------
// Ray spawning

TimedRay spawn_ray(const SurfaceHit& hit, DirectionWorld direction, Time time) {
  Real3 origin =
      kernel::offset_ray_origin(to_kernel(hit.position), hit.position_error, to_kernel(hit.normal), to_kernel(direction));
  return TimedRay{ray<World>{from_kernel<PointWorld>(origin), direction}, time};
}

TimedRay spawn_ray_to(const SurfaceHit& from, PointWorld target, Real3 target_error, Real3 target_normal, Time time,
                      Length& t_max) {
  Real3 start = to_kernel(from.position), end_point = to_kernel(target);
  Real3 origin = kernel::offset_ray_origin(start, from.position_error, to_kernel(from.normal), end_point - start);
  Real3 end = kernel::offset_ray_origin(end_point, target_error, target_normal, origin - end_point);
  Real3 d = end - origin;
  Real distance = kernel::length(d);
  constexpr Real kShadowEpsilon = 1e-4f;  // relative: stop just short of the (offset) light point
  t_max = sg::from_raw<Length>(distance * (1 - kShadowEpsilon));
  return TimedRay{ray<World>{from_kernel<PointWorld>(origin), from_kernel<DirectionWorld>(d * (1.0f / distance))}, time};
}

}  // namespace safegi::render
