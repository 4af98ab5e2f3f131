#include "scene_meshes.hpp"

#include <algorithm>
#include <cmath>

#include "safegi/cpu_renderer/sampling.hpp"

namespace safegi::preview {

namespace {

void add_mesh(SceneMeshes& meshes, const Shape& shape) {
  for (size_t i = 0; i + 2 < shape.indices.size(); i += 3) {
    PointObject a = shape.positions[shape.indices[i]];
    PointObject b = shape.positions[shape.indices[i + 1]];
    PointObject c = shape.positions[shape.indices[i + 2]];
    auto facet = sg::to_normal(sg::normalize(sg::cross(b - a, c - a)));
    for (size_t k = 0; k < 3; ++k) {
      meshes.positions.push_back(shape.positions[shape.indices[i + k]]);
      // A mesh's own vertex normals shade it smoothly, as in the CPU renderer, on the facet's side.
      meshes.normals.push_back(shape.normals.empty() ? facet
                                                     : sg::face_forward(shape.normals[shape.indices[i + k]], sg::to_direction(facet)));
    }
  }
}

void add_sphere(SceneMeshes& meshes, const Shape& shape, int segments) {
  const int rings = std::max(2, segments / 2);
  auto direction_at = [&](int ring, int segment) {
    float theta = kPi * static_cast<float>(ring) / static_cast<float>(rings);
    float phi = 2 * kPi * static_cast<float>(segment) / static_cast<float>(segments);
    return direction<Object>(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
  };
  for (int ring = 0; ring < rings; ++ring)
    for (int segment = 0; segment < segments; ++segment) {
      direction<Object> d00 = direction_at(ring, segment), d01 = direction_at(ring, segment + 1);
      direction<Object> d10 = direction_at(ring + 1, segment), d11 = direction_at(ring + 1, segment + 1);
      for (direction<Object> d : {d00, d10, d11, d00, d11, d01}) {
        meshes.positions.push_back(shape.center + d * shape.radius);
        meshes.normals.push_back(sg::to_normal(d));
      }
    }
}

}  // namespace

SceneMeshes tessellate(const Scene& scene, int sphere_segments) {
  SceneMeshes meshes;
  for (const Shape& shape : scene.shapes) {
    int first = static_cast<int>(meshes.positions.size());
    if (shape.type == Shape::Type::sphere)
      add_sphere(meshes, shape, sphere_segments);
    else
      add_mesh(meshes, shape);
    meshes.ranges.push_back({first, static_cast<int>(meshes.positions.size()) - first});
  }
  return meshes;
}

namespace {

RenderFromObject to_map(const Affine& affine) {
  glm::mat4 forward(1.0f);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) forward[c][r] = affine.m[r][c];
  return sg::from_raw<RenderFromObject>({forward, glm::inverse(forward)});
}

}  // namespace

ScenePoses::ScenePoses(const Scene& scene) : scene_(scene) {
  const Camera& camera = scene.camera;
  bool shutter_open = camera.shutter_close > camera.shutter_open;
  for (const Shape& shape : scene.shapes) {
    if (shutter_open && shape.render_from_object_at_close) {
      motions_.emplace_back(RigidMotion(Affine::from(shape.render_from_object),
                                        Affine::from(*shape.render_from_object_at_close),
                                        sg::raw(camera.shutter_open), sg::raw(camera.shutter_close)));
      animated_ = true;
    } else {
      motions_.emplace_back();
    }
  }
  // Bounds over the shutter: enough poses that a turning object's sweep is covered.
  glm::vec3 lower(INFINITY), upper(-INFINITY);
  constexpr int kPoses = 16;
  for (size_t s = 0; s < scene.shapes.size(); ++s) {
    const Shape& shape = scene.shapes[s];
    for (int k = 0; k <= (motions_[s] ? kPoses : 0); ++k) {
      Time t = camera.shutter_open + (camera.shutter_close - camera.shutter_open) * (static_cast<float>(k) / kPoses);
      RenderFromObject render_from_object = at(s, t);
      auto extend = [&](PointWorld p) {
        lower = glm::min(lower, sg::raw(p));
        upper = glm::max(upper, sg::raw(p));
      };
      if (shape.type == Shape::Type::sphere) {
        Length r = placed_radius(render_from_object, shape.radius);
        PointWorld c = render_from_object(shape.center);
        extend(c + VectorWorld(r, r, r));
        extend(c - VectorWorld(r, r, r));
      } else {
        for (PointObject p : shape.positions) extend(render_from_object(p));
      }
    }
  }
  for (const PointLight& light : scene.point_lights) {
    lower = glm::min(lower, sg::raw(light.position));
    upper = glm::max(upper, sg::raw(light.position));
  }
  for (const SpotLight& light : scene.spot_lights) {
    lower = glm::min(lower, sg::raw(light.position));
    upper = glm::max(upper, sg::raw(light.position));
  }
  if (!(lower.x <= upper.x)) lower = upper = glm::vec3(0.0f);
  center_ = sg::from_raw<PointWorld>(0.5f * (lower + upper));
  radius_ = sg::from_raw<Length>(std::max(0.5f * glm::length(upper - lower), 1e-6f));
}

RenderFromObject ScenePoses::at(size_t shape, Time time) const {
  if (!motions_[shape]) return scene_.shapes[shape].render_from_object;
  return to_map(motions_[shape]->at(sg::raw(time)));
}

Emitter::Emitter(const Scene& scene, int shape_index)
    : Emitter(scene, shape_index, scene.shapes[shape_index].render_from_object) {}

Emitter::Emitter(const Scene& scene, int shape_index, const RenderFromObject& render_from_object)
    : shape_(shape_index),
      radiance_(*scene.shapes[shape_index].emission),
      two_sided_(scene.shapes[shape_index].two_sided_emission) {
  const Shape& shape = scene.shapes[shape_index];
  if (shape.type == Shape::Type::sphere) {
    sphere_ = true;
    center_ = render_from_object(shape.center);
    radius_ = placed_radius(render_from_object, shape.radius);
    area_ = 4 * sg::pi * radius_ * radius_;
    return;
  }
  area_ = append_emitter_triangles(shape, render_from_object, triangles_);
}

EmitterPoint Emitter::sample(float u1, float u2) const {
  if (sphere_) {
    DirectionWorld outward = from_kernel<DirectionWorld>(sample_uniform_sphere(u1, u2));
    return {center_ + outward * radius_, sg::to_normal(outward)};
  }
  // u1 picks the triangle by area, and what is left of it places the point.
  const EmitterTriangle<World>* first = triangles_.data();
  const EmitterTriangle<World>* found = choose_emitter_triangle(first, first + triangles_.size(), u1);
  float low = found == first ? 0.0f : (found - 1)->area_cdf;
  float width = found->area_cdf - low;
  float u = width > 0 ? std::clamp((u1 - low) / width, 0.0f, 0x1.fffffep-1f) : 0.5f;
  TriangleWeights b = uniform_triangle_weights(u, u2);
  return {found->p0 + found->e1 * b.along_e1 + found->e2 * b.along_e2,
          sg::to_normal(sg::normalize(sg::cross(found->e1, found->e2)))};
}

std::vector<Emitter> emitters_of(const Scene& scene) {
  std::vector<Emitter> emitters;
  for (size_t s = 0; s < scene.shapes.size(); ++s) {
    if (!scene.shapes[s].emission) continue;
    Emitter emitter(scene, static_cast<int>(s));
    if (emitter.area() > sg::zero) emitters.push_back(std::move(emitter));
  }
  return emitters;
}

std::optional<Plane> plane_of(const Shape& shape) {
  if (shape.type != Shape::Type::mesh || shape.indices.size() < 3) return std::nullopt;
  // The normal of the largest triangle, the plane through its first vertex.
  float largest = 0;
  Plane plane;
  glm::vec3 lower(INFINITY), upper(-INFINITY);
  for (PointObject p : shape.positions) {
    lower = glm::min(lower, sg::raw(p));
    upper = glm::max(upper, sg::raw(p));
  }
  for (size_t i = 0; i + 2 < shape.indices.size(); i += 3) {
    PointObject a = shape.positions[shape.indices[i]];
    auto n = sg::cross(shape.positions[shape.indices[i + 1]] - a, shape.positions[shape.indices[i + 2]] - a);
    float area = sg::raw(sg::length(n));
    if (area > largest) {
      largest = area;
      plane.point = a;
      plane.unit_normal = sg::to_normal(sg::normalize(n));
    }
  }
  if (!(largest > 0)) return std::nullopt;
  float size = glm::length(upper - lower);
  for (uint32_t index : shape.indices)
    if (std::fabs(sg::raw(sg::dot(plane.unit_normal, shape.positions[index] - plane.point))) > 1e-5f * size) return std::nullopt;
  return plane;
}

void r2_point(uint32_t index, float& u, float& v) {
  constexpr double a1 = 0.7548776662466927, a2 = 0.5698402909980532;  // 1/g, 1/g² for the plastic number g
  double x = 0.5 + a1 * index, y = 0.5 + a2 * index;
  u = static_cast<float>(x - std::floor(x));
  v = static_cast<float>(y - std::floor(y));
}

}  // namespace safegi::preview
