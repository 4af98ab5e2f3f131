#include "geometry.hpp"

#include <cmath>

namespace safegi::render {

using kernel::abs;
using kernel::Bounds3;
using kernel::cross;
using kernel::dot;
using kernel::gamma;

namespace {

Float3 column(const Affine& m, int c) { return {m.m[0][c], m.m[1][c], m.m[2][c]}; }

using kernel::Ray;

Affine inverse(const Affine& a) {
  const auto& m = a.m;
  float c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
  float c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
  float c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
  float det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
  float s = 1.0f / det;
  Affine r;
  r.m[0][0] = c00 * s;
  r.m[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * s;
  r.m[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * s;
  r.m[1][0] = c01 * s;
  r.m[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * s;
  r.m[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * s;
  r.m[2][0] = c02 * s;
  r.m[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * s;
  r.m[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * s;
  Float3 t = r.apply_vector(column(a, 3));
  r.m[0][3] = -t.x;
  r.m[1][3] = -t.y;
  r.m[2][3] = -t.z;
  return r;
}

// Normals transform with the inverse transpose.
Float3 apply_normal(const Affine& inverse_map, Float3 n) {
  const auto& m = inverse_map.m;
  return kernel::normalize({m[0][0] * n.x + m[1][0] * n.y + m[2][0] * n.z, m[0][1] * n.x + m[1][1] * n.y + m[2][1] * n.z,
                            m[0][2] * n.x + m[1][2] * n.y + m[2][2] * n.z});
}

Float3 abs_apply_vector(const Affine& a, Float3 v) {
  Float3 r;
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

}  // namespace

// ---------------------------------------------------------------------------
// PrimitiveSet

void PrimitiveSet::build() {
  std::vector<Bounds3> bounds;
  bounds.reserve(triangles_.size() + spheres_.size());
  for (const Triangle& t : triangles_) {
    Bounds3 b;
    b.extend(t.p0);
    b.extend(t.p0 + t.e1);
    b.extend(t.p0 + t.e2);
    bounds.push_back(b);
  }
  for (const Sphere& s : spheres_) {
    Bounds3 b;
    b.extend(s.center - Float3{s.radius, s.radius, s.radius});
    b.extend(s.center + Float3{s.radius, s.radius, s.radius});
    bounds.push_back(b);
  }
  bvh_ = kernel::Bvh(bounds);
}

template <bool any_hit>
bool PrimitiveSet::trace(const Ray& ray, float& t_max, uint32_t& primitive, float& b1, float& b2) const {
  kernel::TraversalRay traversal(ray.origin, ray.direction);
  const uint32_t triangle_count = static_cast<uint32_t>(triangles_.size());
  return bvh_.traverse<any_hit>(traversal, t_max, [&](uint32_t index, float& t_limit) {
    if (index < triangle_count) {
      // Möller–Trumbore.
      const Triangle& tri = triangles_[index];
      Float3 p = cross(ray.direction, tri.e2);
      float det = dot(tri.e1, p);
      if (det == 0.0f) return false;
      float inverse_det = 1.0f / det;
      Float3 s = ray.origin - tri.p0;
      float u = dot(s, p) * inverse_det;
      if (u < 0.0f || u > 1.0f) return false;
      Float3 q = cross(s, tri.e1);
      float v = dot(ray.direction, q) * inverse_det;
      if (v < 0.0f || u + v > 1.0f) return false;
      float t = dot(tri.e2, q) * inverse_det;
      if (!(t > 0.0f && t < t_limit)) return false;
      t_limit = t;
      primitive = index;
      b1 = u;
      b2 = v;
      return true;
    }
    // Sphere, with the discriminant computed from the perpendicular offset for
    // precision far from the sphere (Ray Tracing Gems, ch. 7).
    const Sphere& sphere = spheres_[index - triangle_count];
    Float3 oc = ray.origin - sphere.center;
    float b = dot(oc, ray.direction);
    Float3 perpendicular = oc - ray.direction * b;
    float r2 = sphere.radius * sphere.radius;
    float discriminant = r2 - dot(perpendicular, perpendicular);
    if (discriminant < 0.0f) return false;
    float c = dot(oc, oc) - r2;
    float q = -b - std::copysign(std::sqrt(discriminant), b);
    float t_near = c / q, t_far = q;
    if (t_near > t_far) std::swap(t_near, t_far);
    // Outside (c > 0) only the near root is a first hit; inside only the far one.
    float t = c > 0.0f ? t_near : t_far;
    if (!(t > 0.0f && t < t_limit)) return false;
    t_limit = t;
    primitive = index;
    return true;
  });
}

std::optional<kernel::Hit> PrimitiveSet::intersect(const Ray& ray, float t_max) const {
  uint32_t primitive = 0;
  float b1 = 0, b2 = 0;
  if (!trace<false>(ray, t_max, primitive, b1, b2)) return std::nullopt;
  kernel::Hit hit;
  hit.distance = t_max;
  if (primitive < triangles_.size()) {
    const Triangle& tri = triangles_[primitive];
    Float3 along_u = tri.e1 * b1, along_v = tri.e2 * b2;
    hit.position = tri.p0 + along_u + along_v;
    hit.position_error = (abs(tri.p0) + abs(along_u) + abs(along_v)) * gamma(7);
    hit.normal = kernel::normalize(cross(tri.e1, tri.e2));
    hit.shape = tri.shape;
  } else {
    const Sphere& sphere = spheres_[primitive - triangles_.size()];
    Float3 relative = ray.origin + ray.direction * t_max - sphere.center;
    relative = relative * (sphere.radius / kernel::length(relative));  // reproject onto the surface
    hit.position = sphere.center + relative;
    hit.position_error = (abs(relative) + abs(sphere.center)) * gamma(6);
    hit.normal = relative * (1.0f / sphere.radius);
    hit.shape = sphere.shape;
  }
  return hit;
}

bool PrimitiveSet::occluded(const Ray& ray, float t_max) const {
  uint32_t primitive = 0;
  float b1 = 0, b2 = 0;
  return trace<true>(ray, t_max, primitive, b1, b2);
}

// ---------------------------------------------------------------------------
// RigidMotion

RigidMotion::Pose RigidMotion::decompose(const Affine& m) {
  Pose pose;
  pose.translation = column(m, 3);
  // Polar decomposition M = R S by averaging R with its inverse transpose.
  Affine rotation = m;
  for (int r = 0; r < 3; ++r) rotation.m[r][3] = 0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    Affine inv = inverse(rotation);
    Affine next;
    float change = 0;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        next.m[r][c] = 0.5f * (rotation.m[r][c] + inv.m[c][r]);
        change = std::fmax(change, std::fabs(next.m[r][c] - rotation.m[r][c]));
      }
    rotation = next;
    if (change < 1e-7f) break;
  }
  Affine scale = inverse(rotation) * m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) pose.scale[r][c] = scale.m[r][c];
  // Rotation matrix to quaternion.
  const auto& R = rotation.m;
  float trace = R[0][0] + R[1][1] + R[2][2];
  float* q = pose.rotation;
  if (trace > 0) {
    float s = std::sqrt(trace + 1.0f) * 2;
    q[3] = 0.25f * s;
    q[0] = (R[2][1] - R[1][2]) / s;
    q[1] = (R[0][2] - R[2][0]) / s;
    q[2] = (R[1][0] - R[0][1]) / s;
  } else if (R[0][0] > R[1][1] && R[0][0] > R[2][2]) {
    float s = std::sqrt(1.0f + R[0][0] - R[1][1] - R[2][2]) * 2;
    q[3] = (R[2][1] - R[1][2]) / s;
    q[0] = 0.25f * s;
    q[1] = (R[0][1] + R[1][0]) / s;
    q[2] = (R[0][2] + R[2][0]) / s;
  } else if (R[1][1] > R[2][2]) {
    float s = std::sqrt(1.0f + R[1][1] - R[0][0] - R[2][2]) * 2;
    q[3] = (R[0][2] - R[2][0]) / s;
    q[0] = (R[0][1] + R[1][0]) / s;
    q[1] = 0.25f * s;
    q[2] = (R[1][2] + R[2][1]) / s;
  } else {
    float s = std::sqrt(1.0f + R[2][2] - R[0][0] - R[1][1]) * 2;
    q[3] = (R[1][0] - R[0][1]) / s;
    q[0] = (R[0][2] + R[2][0]) / s;
    q[1] = (R[1][2] + R[2][1]) / s;
    q[2] = 0.25f * s;
  }
  return pose;
}

RigidMotion::RigidMotion(const Affine& at_open, const Affine& at_close, float time_open, float time_close)
    : open_(decompose(at_open)), close_(decompose(at_close)), time_open_(time_open), time_close_(time_close) {
  // Take the shorter arc.
  float d = 0;
  for (int i = 0; i < 4; ++i) d += open_.rotation[i] * close_.rotation[i];
  if (d < 0)
    for (float& c : close_.rotation) c = -c;
}

Affine RigidMotion::at(float time) const {
  float span = time_close_ - time_open_;
  float s = span > 0 ? std::clamp((time - time_open_) / span, 0.0f, 1.0f) : 0.0f;
  Float3 translation = open_.translation * (1 - s) + close_.translation * s;
  // Slerp, falling back to a normalised lerp for nearly equal rotations.
  float cos_theta = 0;
  for (int i = 0; i < 4; ++i) cos_theta += open_.rotation[i] * close_.rotation[i];
  float q[4];
  if (cos_theta > 0.9995f) {
    float norm = 0;
    for (int i = 0; i < 4; ++i) {
      q[i] = open_.rotation[i] * (1 - s) + close_.rotation[i] * s;
      norm += q[i] * q[i];
    }
    for (float& c : q) c /= std::sqrt(norm);
  } else {
    float theta = std::acos(std::clamp(cos_theta, -1.0f, 1.0f));
    float a = std::sin((1 - s) * theta) / std::sin(theta), b = std::sin(s * theta) / std::sin(theta);
    for (int i = 0; i < 4; ++i) q[i] = open_.rotation[i] * a + close_.rotation[i] * b;
  }
  float x = q[0], y = q[1], z = q[2], w = q[3];
  Affine rotation;
  rotation.m[0][0] = 1 - 2 * (y * y + z * z);
  rotation.m[0][1] = 2 * (x * y - z * w);
  rotation.m[0][2] = 2 * (x * z + y * w);
  rotation.m[1][0] = 2 * (x * y + z * w);
  rotation.m[1][1] = 1 - 2 * (x * x + z * z);
  rotation.m[1][2] = 2 * (y * z - x * w);
  rotation.m[2][0] = 2 * (x * z - y * w);
  rotation.m[2][1] = 2 * (y * z + x * w);
  rotation.m[2][2] = 1 - 2 * (x * x + y * y);
  Affine scale;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) scale.m[r][c] = open_.scale[r][c] * (1 - s) + close_.scale[r][c] * s;
  Affine result = rotation * scale;
  for (int r = 0; r < 3; ++r) result.m[r][3] = translation[r];
  return result;
}

// ---------------------------------------------------------------------------
// Geometry

namespace {

float uniform_scale(const Affine& m) { return kernel::length(column(m, 0)); }

// Adds a shape in world space (`to_world` given) or in its own object space.
void add_shape(PrimitiveSet& set, const Shape& shape, uint32_t index, const ObjectToWorld* to_world) {
  auto place = [&](PointObject p) { return to_world ? to_kernel((*to_world)(p)) : to_kernel(p); };
  if (shape.type == Shape::Type::sphere) {
    float scale = to_world ? uniform_scale(Affine::from(*to_world)) : 1.0f;
    set.add_sphere(place(shape.center), sg::raw(shape.radius) * scale, index);
    return;
  }
  for (size_t i = 0; i + 2 < shape.indices.size(); i += 3)
    set.add_triangle(place(shape.positions[shape.indices[i]]), place(shape.positions[shape.indices[i + 1]]),
                     place(shape.positions[shape.indices[i + 2]]), index);
}

}  // namespace

Affine Affine::from(const ObjectToWorld& map) {
  glm::mat4 forward = sg::raw(map).forward;  // column-major
  Affine a;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) a.m[r][c] = forward[c][r];
  return a;
}

Geometry::Geometry(const Scene& scene) {
  bool shutter_open = scene.camera.shutter_close > scene.camera.shutter_open;
  float time_open = sg::raw(scene.camera.shutter_open), time_close = sg::raw(scene.camera.shutter_close);
  for (uint32_t i = 0; i < scene.shapes.size(); ++i) {
    const Shape& shape = scene.shapes[i];
    if (shutter_open && shape.render_from_object_at_close) {
      Instance instance{PrimitiveSet{},
                        RigidMotion(Affine::from(shape.render_from_object),
                                    Affine::from(*shape.render_from_object_at_close), time_open, time_close),
                        Bounds3{}};
      add_shape(instance.primitives, shape, i, nullptr);
      instance.primitives.build();
      constexpr int kPoseSamples = 64;  // bounds of the poses along the motion, padded below
      for (int s = 0; s <= kPoseSamples; ++s) {
        float time = time_open + (time_close - time_open) * static_cast<float>(s) / kPoseSamples;
        instance.swept_bounds.extend(transform_bounds(instance.motion.at(time), instance.primitives.bounds()));
      }
      Float3 pad = instance.swept_bounds.extent() * 0.01f;
      instance.swept_bounds.lower = instance.swept_bounds.lower - pad;
      instance.swept_bounds.upper = instance.swept_bounds.upper + pad;
      bounds_.extend(instance.swept_bounds);
      instances_.push_back(std::move(instance));
    } else {
      add_shape(static_primitives_, shape, i, &shape.render_from_object);
    }
  }
  static_primitives_.build();
  if (!static_primitives_.empty()) bounds_.extend(static_primitives_.bounds());
}

std::optional<SurfaceHit> Geometry::intersect(const TimedRay& typed_ray) const {
  Ray ray{to_kernel(typed_ray.o), to_kernel(typed_ray.d), sg::raw(typed_ray.time)};
  float t_max = kernel::kInfinity;
  std::optional<kernel::Hit> hit = static_primitives_.intersect(ray, t_max);
  if (hit) t_max = hit->distance;
  for (const Instance& instance : instances_) {
    if (!kernel::intersect_bounds(instance.swept_bounds, kernel::TraversalRay(ray.origin, ray.direction), t_max))
      continue;
    Affine render_from_object = instance.motion.at(ray.time);
    Affine object_from_render = inverse(render_from_object);
    Float3 direction = object_from_render.apply_vector(ray.direction);
    float stretch = kernel::length(direction);
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
                    sg::from_raw<Length>(hit->distance), hit->shape};
}

bool Geometry::occluded(const TimedRay& typed_ray, Length typed_t_max) const {
  Ray ray{to_kernel(typed_ray.o), to_kernel(typed_ray.d), sg::raw(typed_ray.time)};
  float t_max = sg::raw(typed_t_max);
  if (static_primitives_.occluded(ray, t_max)) return true;
  for (const Instance& instance : instances_) {
    if (!kernel::intersect_bounds(instance.swept_bounds, kernel::TraversalRay(ray.origin, ray.direction), t_max))
      continue;
    Affine object_from_render = inverse(instance.motion.at(ray.time));
    Float3 direction = object_from_render.apply_vector(ray.direction);
    float stretch = kernel::length(direction);
    Ray local{object_from_render.apply_point(ray.origin), direction * (1.0f / stretch), ray.time};
    if (instance.primitives.occluded(local, t_max * stretch)) return true;
  }
  return false;
}

// ---------------------------------------------------------------------------
// Ray spawning

TimedRay spawn_ray(const SurfaceHit& hit, DirectionWorld direction, Time time) {
  Float3 origin =
      kernel::offset_ray_origin(to_kernel(hit.position), hit.position_error, to_kernel(hit.normal), to_kernel(direction));
  return TimedRay{ray<World>{from_kernel<PointWorld>(origin), direction}, time};
}

TimedRay spawn_ray_to(const SurfaceHit& from, PointWorld target, Float3 target_error, Float3 target_normal, Time time,
                      Length& t_max) {
  Float3 start = to_kernel(from.position), end_point = to_kernel(target);
  Float3 origin = kernel::offset_ray_origin(start, from.position_error, to_kernel(from.normal), end_point - start);
  Float3 end = kernel::offset_ray_origin(end_point, target_error, target_normal, origin - end_point);
  Float3 d = end - origin;
  float distance = kernel::length(d);
  constexpr float kShadowEpsilon = 1e-4f;  // relative: stop just short of the (offset) light point
  t_max = sg::from_raw<Length>(distance * (1 - kShadowEpsilon));
  return TimedRay{ray<World>{from_kernel<PointWorld>(origin), from_kernel<DirectionWorld>(d * (1.0f / distance))}, time};
}

}  // namespace safegi::render
