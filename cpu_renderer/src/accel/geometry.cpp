#include "accel/geometry.hpp"

#include "textures/surface_texture.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

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

using kernel::triangle_block_detail::Double3;
using kernel::triangle_block_detail::to_double;

}  // namespace

// ---------------------------------------------------------------------------
// PrimitiveSet

void PrimitiveSet::build(int threads) {
  build_triangles(threads);
  build_spheres(threads);
}

// Builds the triangles' hierarchy and packs each leaf's triangles into blocks
// of four from a block boundary on, so that one vector test takes a leaf's
// triangles and the leaf's memory is whole cache lines of its own.
void PrimitiveSet::build_triangles(int threads) {
  const uint32_t count = static_cast<uint32_t>(triangles_.size());
  if (count == 0) return;
  constexpr uint32_t kWidth = kernel::TriangleBlock::kWidth;
  triangle_bvh_ = kernel::Bvh8(
      count,
      [&](uint32_t i) {
        const Triangle& t = triangles_[i];
        Bounds3 b;
        b.extend(t.p0);
        b.extend(t.p0 + t.e1);
        b.extend(t.p0 + t.e2);
        return b;
      },
      kernel::Bvh8::kDefaultMaxLeafSize, threads, kWidth);
  const std::vector<uint32_t> order = triangle_bvh_.take_primitive_order();
  struct Leaf {
    uint32_t first_entry, count, first_block;
  };
  std::vector<Leaf> leaves;
  for (const kernel::Bvh8::Node& node : triangle_bvh_.nodes())
    for (int i = 0; i < kernel::Bvh8::Node::kWidth; ++i)
      if (node.primitive_count[i] > 0) leaves.push_back({node.child[i], node.primitive_count[i], 0});
  std::sort(leaves.begin(), leaves.end(), [](const Leaf& a, const Leaf& b) { return a.first_entry < b.first_entry; });
  // A leaf's first block, looked up by its first entry below.
  std::vector<uint32_t> block_of_entry(count);
  uint32_t blocks = 0;
  for (Leaf& leaf : leaves) {
    leaf.first_block = block_of_entry[leaf.first_entry] = blocks;
    blocks += (leaf.count + kWidth - 1) / kWidth;
  }
  triangle_blocks_.resize(blocks);
  const uint32_t leaf_count = static_cast<uint32_t>(leaves.size());
  kernel::for_each_chunk(leaf_count, leaf_count >= kernel::kParallelMinimum ? threads : 1,
                         [&](int, uint32_t begin, uint32_t end) {
                           for (uint32_t l = begin; l < end; ++l)
                             for (uint32_t k = 0; k < leaves[l].count; ++k) {
                               const Triangle& t = triangles_[order[leaves[l].first_entry + k]];
                               triangle_blocks_[leaves[l].first_block + k / kWidth].set(
                                   static_cast<int>(k % kWidth), t.p0, t.e1, t.e2, t.shape, t.face);
                             }
                         });
  triangle_bvh_.renumber_leaves([&](uint32_t first_entry, uint32_t) { return block_of_entry[first_entry]; });
  std::vector<Triangle>().swap(triangles_);
}

void PrimitiveSet::build_spheres(int threads) {
  const uint32_t count = static_cast<uint32_t>(spheres_.size());
  if (count == 0) return;
  sphere_bvh_ = kernel::Bvh(
      count,
      [&](uint32_t i) {
        const Sphere& s = spheres_[i];
        const Real3 radius{s.radius, s.radius, s.radius};
        Bounds3 b;
        b.extend(s.center - radius);
        b.extend(s.center + radius);
        return b;
      },
      kernel::Bvh::kDefaultMaxLeafSize, threads);
  const std::vector<uint32_t> order = sphere_bvh_.take_primitive_order();
  std::vector<Sphere> ordered(count);
  for (uint32_t k = 0; k < count; ++k) ordered[k] = spheres_[order[k]];
  spheres_ = std::move(ordered);
}

Bounds3 PrimitiveSet::bounds() const {
  Bounds3 b = triangle_bvh_.bounds();
  if (!sphere_bvh_.empty()) b.extend(sphere_bvh_.bounds());
  return b;
}

size_t PrimitiveSet::memory_bytes() const {
  return triangle_blocks_.capacity() * sizeof(kernel::TriangleBlock) + spheres_.capacity() * sizeof(Sphere) +
         triangle_bvh_.memory_bytes() + sphere_bvh_.memory_bytes();
}

struct PrimitiveSet::Found {
  bool sphere = false;
  uint32_t index = 0;  // triangle: block · 4 + lane; sphere: into spheres_
  Real b1 = 0, b2 = 0;
};

template <bool any_hit, bool skipping>
bool PrimitiveSet::trace_triangles(const Ray& ray, const kernel::TraversalRay& traversal, Real& t_max, Found& found,
                                   std::span<const kernel::PrimitiveId> skipped) const {
  constexpr uint32_t kWidth = kernel::TriangleBlock::kWidth;
  const kernel::BlockRay block_ray(ray.origin, ray.direction);
  // The traversal says how many lanes its vectors hold: with eight (AVX2), a
  // leaf's blocks are tested two at a time while more than one block's
  // triangles are left. The lanes come out in the same order either way, so
  // the exact test sees the same triangles in the same order.
  auto test_leaf = [&](uint32_t first_block, uint32_t count, Real& t_limit, auto vector_width) {
    bool hit = false;
    for (uint32_t block = first_block; count > 0;) {
      const bool pair = decltype(vector_width)::value >= 2 * kWidth && count > kWidth;
      const int lanes = static_cast<int>(std::min(count, pair ? 2 * kWidth : kWidth));
      count -= static_cast<uint32_t>(lanes);
      const uint32_t first = block;
      block += pair ? 2 : 1;
      const kernel::TriangleBlock& first_triangles = triangle_blocks_[first];
      unsigned candidates = pair ? kernel::candidate_lanes<2 * kWidth>(first_triangles, block_ray, t_limit, lanes)
                                 : kernel::candidate_lanes(first_triangles, block_ray, t_limit, lanes);
      for (; candidates != 0; candidates &= candidates - 1) {
        const uint32_t index = first * kWidth + static_cast<uint32_t>(std::countr_zero(candidates));
        const kernel::TriangleBlock& triangles = triangle_blocks_[index / kWidth];
        const int lane = static_cast<int>(index % kWidth);
        if constexpr (skipping)
          if (std::ranges::any_of(skipped, [&](kernel::PrimitiveId id) {
                return id.shape == triangles.shape[lane] && id.face == triangles.face[lane];
              }))
            continue;
        Real b1, b2;
        if (!kernel::intersect_lane(triangles, lane, block_ray, t_limit, b1, b2)) continue;
        found = {false, index, b1, b2};
        hit = true;
        if constexpr (any_hit) return true;
      }
    }
    return hit;
  };
  auto prefetch_leaf = [&](uint32_t first_block, uint32_t count) {
    const char* block = reinterpret_cast<const char*>(&triangle_blocks_[first_block]);
    const uint32_t lines = std::min<uint32_t>(2, (count + kWidth - 1) / kWidth) * sizeof(kernel::TriangleBlock) / 64;
    for (uint32_t line = 0; line < lines; ++line) __builtin_prefetch(block + 64 * line);
  };
  return kernel::traversal_uses_avx2 ? triangle_bvh_.traverse_avx2<any_hit>(traversal, t_max, test_leaf, prefetch_leaf)
                                     : triangle_bvh_.traverse<any_hit>(traversal, t_max, test_leaf, prefetch_leaf);
}

template <bool any_hit>
bool PrimitiveSet::trace_spheres(const Ray& ray, const kernel::TraversalRay& traversal, Real& t_max,
                                 Found& found) const {
  auto test_leaf = [&](uint32_t first, uint32_t count, Real& t_limit, auto) {
    bool hit = false;
    for (uint32_t index = first; index < first + count; ++index) {
      // The discriminant from the perpendicular offset, for precision far from
      // the sphere (Ray Tracing Gems, ch. 7).
      const Sphere& sphere = spheres_[index];
      Real3 oc = ray.origin - sphere.center;
      Real b = dot(oc, ray.direction);
      Real3 perpendicular = oc - ray.direction * b;
      Real r2 = sphere.radius * sphere.radius;
      Real discriminant = r2 - dot(perpendicular, perpendicular);
      if (discriminant < 0.0f) continue;
      Real c = dot(oc, oc) - r2;
      Real q = -b - std::copysign(std::sqrt(discriminant), b);
      Real t_near = c / q, t_far = q;
      if (t_near > t_far) std::swap(t_near, t_far);
      // Outside (c > 0) only the near root is a first hit; inside only the far one.
      Real t = c > 0.0f ? t_near : t_far;
      if (!(t > 0.0f && t < t_limit)) continue;
      t_limit = t;
      found = {true, index, 0, 0};
      hit = true;
      if constexpr (any_hit) return true;
    }
    return hit;
  };
  return sphere_bvh_.traverse<any_hit>(traversal, t_max, test_leaf, [](uint32_t, uint32_t) {});
}

template <bool any_hit>
bool PrimitiveSet::trace(const Ray& ray, Real& t_max, Found& found, std::span<const kernel::PrimitiveId> skipped) const {
  const kernel::TraversalRay traversal(ray.origin, ray.direction);
  // The skipping test only where there is something to skip (alpha masks), out of the hot loop otherwise.
  const bool triangle_hit = skipped.empty() ? trace_triangles<any_hit, false>(ray, traversal, t_max, found, skipped)
                                            : trace_triangles<any_hit, true>(ray, traversal, t_max, found, skipped);
  if (any_hit && triangle_hit) return true;
  return trace_spheres<any_hit>(ray, traversal, t_max, found) || triangle_hit;
}

std::optional<kernel::Hit> PrimitiveSet::intersect(const Ray& ray, Real t_max,
                                                   std::span<const kernel::PrimitiveId> skipped) const {
  Found found;
  if (!trace<false>(ray, t_max, found, skipped)) return std::nullopt;
  kernel::Hit hit;
  hit.distance = t_max;
  if (!found.sphere) {
    constexpr uint32_t kWidth = kernel::TriangleBlock::kWidth;
    const kernel::TriangleBlock& block = triangle_blocks_[found.index / kWidth];
    const int lane = static_cast<int>(found.index % kWidth);
    const Triangle tri{block.vertex(lane), block.edge1(lane), block.edge2(lane), block.shape[lane], block.face[lane]};
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
      Real3 along_u = tri.e1 * found.b1, along_v = tri.e2 * found.b2;
      hit.position = tri.p0 + along_u + along_v;
      hit.position_error = (abs(tri.p0) + abs(along_u) + abs(along_v)) * gamma(7);
    }
    hit.normal = kernel::normalize(cross(tri.e1, tri.e2));
    hit.shape = tri.shape;
    hit.face = tri.face;
  } else {
    const Sphere& sphere = spheres_[found.index];
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
  Found found;
  return trace<true>(ray, t_max, found);
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
  for (uint32_t i = 0; i < scene.shapes.size(); ++i) {
    const Shape& shape = scene.shapes[i];
    if (std::optional<RigidMotion> motion = motion_of(shape, scene.camera)) {
      Instance instance{PrimitiveSet{}, *motion, Bounds3{}};
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
    return mask && sg::raw(mask_textures_->reflectance_at(*mask, hit, ConeFootprint{}, time)).x == 0;
  };
  return zero_at_hit(shape.alpha) || (shadow && zero_at_hit(shape.shadow_alpha));
}

std::optional<SurfaceHit> Geometry::nearest_unmasked(const TimedRay& ray, Length t_max, bool shadow) const {
  // A bound on the layers one ray passes (foliage has tens); beyond it the
  // last hit counts as opaque, so that no ray can loop.
  constexpr int kMaxMaskedLayers = 4096;
  // The masked triangles met since the ray last moved on: the ray is traced
  // again from the same origin without them. Past kMaxSkipped (a stack of
  // masked layers) it goes on from just beyond the last one, which passes any
  // surface within rounding of that one's plane too.
  constexpr size_t kMaxSkipped = 16;
  std::array<kernel::PrimitiveId, kMaxSkipped> skipped;
  size_t skipped_count = 0;
  TimedRay beyond = ray;
  bool moved_on = false;
  for (int layer = 0; layer < kMaxMaskedLayers; ++layer) {
    std::optional<SurfaceHit> hit = nearest(beyond, std::span(skipped.data(), skipped_count));
    if (!hit) return std::nullopt;
    // Distances along the original ray, from its origin.
    if (moved_on) hit->distance = sg::dot(hit->position - ray.o, ray.d);
    if (hit->distance >= t_max) return std::nullopt;
    if (!masked(*hit, ray.time, shadow) || layer + 1 == kMaxMaskedLayers) return hit;
    if (skipped_count == kMaxSkipped) {
      skipped_count = 0;
      beyond = spawn_ray(*hit, ray.d, ray.time);
      moved_on = true;
    }
    skipped[skipped_count++] = {hit->shape, hit->face};
  }
  return std::nullopt;
}

std::optional<SurfaceHit> Geometry::nearest(const TimedRay& typed_ray, std::span<const kernel::PrimitiveId> skipped) const {
  Ray ray{to_kernel(typed_ray.o), to_kernel(typed_ray.d), sg::raw(typed_ray.time)};
  Real t_max = kernel::kInfinity;
  std::optional<kernel::Hit> hit = static_primitives_.intersect(ray, t_max, skipped);
  if (hit) t_max = hit->distance;
  for (const Instance& instance : instances_) {
    if (!kernel::intersect_bounds(instance.swept_bounds, kernel::TraversalRay(ray.origin, ray.direction), t_max))
      continue;
    Affine render_from_object = instance.motion.at(ray.time);
    Affine object_from_render = inverse(render_from_object);
    Real3 direction = object_from_render.apply_vector(ray.direction);
    Real stretch = kernel::length(direction);
    Ray local{object_from_render.apply_point(ray.origin), direction * (1.0f / stretch), ray.time};
    std::optional<kernel::Hit> local_hit = instance.primitives.intersect(local, t_max * stretch, skipped);
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
