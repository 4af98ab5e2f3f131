#include "scene_packing.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <variant>

#include "accel/bvh.hpp"  // cpu_renderer's BVH: the GPU walks the nodes it builds
#include "safegi/cpu_renderer/types.hpp"

namespace safegi::gpu {
namespace {

using render::kernel::Bounds3;
using render::kernel::Bvh;
using render::kernel::Real3;
using render::kernel::WideBvhNode;

struct Triangle {
  PointWorld p0, p1, p2;
  std::uint32_t shape;
};
struct Sphere {
  PointWorld center;
  Length radius;
  std::uint32_t shape;
};

Real3 kernel_point(PointWorld p) { return render::to_kernel(p); }

// Appends `bvh`'s nodes, their interior children numbered from `first_node`.
void append_nodes(PackedScene& packed, const Bvh& bvh, std::uint32_t first_node) {
  for (const WideBvhNode& node : bvh.nodes()) {
    for (int axis = 0; axis < 3; ++axis)
      for (int child = 0; child < WideBvhNode::kWidth; ++child) {
        packed.node_lower.push_back(sg::from_raw<Length>(node.lower[axis][child]));
        packed.node_upper.push_back(sg::from_raw<Length>(node.upper[axis][child]));
      }
    for (int child = 0; child < WideBvhNode::kWidth; ++child) {
      const bool occupied = (node.occupied >> child) & 1u;
      const std::uint32_t count = occupied ? node.primitive_count[child] : 0u;
      packed.node_child.push_back(!occupied ? kNone : count > 0 ? node.child[child] : node.child[child] + first_node);
      packed.node_primitive_count.push_back(count);
    }
  }
}

std::uint32_t index_of(std::size_t i) { return static_cast<std::uint32_t>(i); }

void pack_materials(const Scene& scene, PackedScene& packed) {
  for (const render::Material& material : scene.materials) {
    MaterialKind kind = MaterialKind::black;
    Reflectance diffuse{}, specular{}, transmittance{};
    float exponent = 1, alpha = 0, ior = 1.5f;
    bool swapped = false;
    auto note_texture = [&](const render::TexturedReflectance& r) {
      if (r.textured())
        packed.unsupported.push_back("material '" + material.name + "': texture (its constant factor is used)");
      return r.value;
    };
    if (material.mix) packed.unsupported.push_back("material '" + material.name + "': mix (drawn black)");
    if (material.bump) packed.unsupported.push_back("material '" + material.name + "': bump map (ignored)");
    std::visit(render::Overloaded{
                   [&](const render::LambertMaterial& m) {
                     kind = MaterialKind::lambert;
                     diffuse = note_texture(m.diffuse);
                   },
                   [&](const render::PhongMaterial& m) {
                     kind = MaterialKind::phong;
                     diffuse = note_texture(m.diffuse);
                     specular = m.specular;
                     exponent = m.exponent;
                   },
                   [&](const render::PlasticMaterial& m) {
                     kind = MaterialKind::plastic;
                     diffuse = note_texture(m.diffuse);
                     specular = m.specular;
                     alpha = m.alpha;
                     ior = m.ior;
                     swapped = m.pbrt_v3_fresnel;
                   },
                   [&](const render::MirrorMaterial& m) {
                     kind = MaterialKind::mirror;
                     specular = m.reflectance;
                   },
                   [&](const render::GlassMaterial& m) {
                     kind = MaterialKind::glass;
                     specular = m.reflectance;
                     transmittance = m.transmittance;
                     ior = m.ior;
                   },
                   [&](const render::BlackMaterial&) {},
                   [&](const auto&) {
                     packed.unsupported.push_back("material '" + material.name + "': this model (drawn black)");
                   },
               },
               material.model);
    if (material.mix) kind = MaterialKind::black;
    packed.material_kind.push_back(static_cast<std::uint32_t>(kind));
    packed.material_diffuse.push_back(diffuse);
    packed.material_specular.push_back(specular);
    packed.material_transmittance.push_back(transmittance);
    packed.material_exponent.push_back(exponent);
    packed.material_alpha.push_back(alpha);
    packed.material_ior.push_back(ior);
    packed.material_swapped_fresnel.push_back(swapped ? 1u : 0u);
  }
}

void add_light(PackedScene& packed, LightKind kind, std::uint32_t primitive) {
  packed.light_kind.push_back(static_cast<std::uint32_t>(kind));
  packed.light_primitive.push_back(primitive);
  packed.light_position.push_back(PointWorld{});
  packed.light_intensity.push_back(Intensity{});
  packed.light_axis.push_back(DirectionWorld{});
  packed.light_cos_cone.push_back(0);
  packed.light_cos_cone.push_back(0);
  packed.light_irradiance.push_back(NormalIrradiance{});
}

void pack_camera(const Scene& scene, int width, int height, FrameValues& frame) {
  const render::Camera& camera = scene.camera;
  frame.camera_position = camera.position;
  frame.camera_forward = sg::normalize(camera.look_at - camera.position);
  frame.camera_right = sg::normalize(sg::cross(frame.camera_forward, camera.up));
  frame.camera_up = sg::normalize(sg::cross(frame.camera_right, frame.camera_forward));
  const float shorter = static_cast<float>(std::min(width, height));
  const float tangent = sg::tan(0.5f * camera.fov);
  frame.image_half_width = tangent * static_cast<float>(width) / shorter;
  frame.image_half_height = tangent * static_cast<float>(height) / shorter;
  frame.lens_radius = camera.lens_radius;
  frame.focus_distance = camera.focus_distance;
  frame.image_width = static_cast<std::uint32_t>(width);
  frame.image_height = static_cast<std::uint32_t>(height);
}

}  // namespace

PackedScene pack_scene(const Scene& scene, int width, int height) {
  PackedScene packed;
  if (scene.camera.projection != render::CameraProjection::perspective)
    packed.unsupported.push_back("camera: only the perspective projection (drawn as one)");
  if (!scene.media.empty()) packed.unsupported.push_back("participating media (ignored)");
  pack_camera(scene, width, height, packed.frame);
  pack_materials(scene, packed);

  std::vector<Triangle> triangles;
  std::vector<Sphere> spheres;
  for (std::size_t s = 0; s < scene.shapes.size(); ++s) {
    const render::Shape& shape = scene.shapes[s];
    const bool drawn = !shape.invisible && shape.material >= 0;
    packed.shape_material.push_back(drawn ? index_of(static_cast<std::size_t>(shape.material)) : kNone);
    packed.shape_emission.push_back(shape.emission ? *shape.emission : Radiance{});
    packed.shape_two_sided.push_back(shape.two_sided_emission ? 1u : 0u);
    if (shape.render_from_object_at_close) packed.unsupported.push_back("shape '" + shape.name + "': motion (drawn at shutter open)");
    if (shape.alpha || shape.shadow_alpha) packed.unsupported.push_back("shape '" + shape.name + "': alpha mask (ignored)");
    if (!shape.normals.empty()) packed.unsupported.push_back("shape '" + shape.name + "': shading normals (geometric ones used)");
    if (shape.invisible && !shape.emission) continue;
    if (shape.type == render::Shape::Type::sphere) {
      spheres.push_back({shape.render_from_object(shape.center), render::placed_radius(shape.render_from_object, shape.radius),
                         index_of(s)});
      continue;
    }
    for (std::size_t i = 0; i + 2 < shape.indices.size(); i += 3)
      triangles.push_back({shape.render_from_object(shape.positions[shape.indices[i]]),
                           shape.render_from_object(shape.positions[shape.indices[i + 1]]),
                           shape.render_from_object(shape.positions[shape.indices[i + 2]]), index_of(s)});
  }
  if (triangles.empty() && spheres.empty()) throw std::runtime_error("the scene has no shapes the GPU renderer draws");

  Bounds3 scene_bounds;
  Bvh triangle_bvh(index_of(triangles.size()), [&](std::uint32_t i) {
    Bounds3 b;
    b.extend(kernel_point(triangles[i].p0));
    b.extend(kernel_point(triangles[i].p1));
    b.extend(kernel_point(triangles[i].p2));
    return b;
  }, Bvh::kDefaultMaxLeafSize, 1);
  Bvh sphere_bvh(index_of(spheres.size()), [&](std::uint32_t i) {
    const Real3 c = kernel_point(spheres[i].center);
    const float r = sg::raw(spheres[i].radius);
    Bounds3 b;
    b.extend(c - Real3{r, r, r});
    b.extend(c + Real3{r, r, r});
    return b;
  }, Bvh::kDefaultMaxLeafSize, 1);
  if (!triangle_bvh.empty()) {
    packed.frame.triangle_root = 0;
    scene_bounds.extend(triangle_bvh.bounds());
  }
  append_nodes(packed, triangle_bvh, 0);
  if (!sphere_bvh.empty()) {
    packed.frame.sphere_root = index_of(triangle_bvh.nodes().size());
    scene_bounds.extend(sphere_bvh.bounds());
  }
  append_nodes(packed, sphere_bvh, index_of(triangle_bvh.nodes().size()));

  // Primitives in leaf order; every emitting one is a light of its own.
  for (std::uint32_t entry : triangle_bvh.take_primitive_order()) {
    const Triangle& t = triangles[entry];
    packed.triangle_vertex.insert(packed.triangle_vertex.end(), {t.p0, t.p1, t.p2});
    packed.triangle_shape.push_back(t.shape);
    const bool emits = scene.shapes[t.shape].emission.has_value();
    packed.triangle_light.push_back(emits ? index_of(packed.light_kind.size()) : kNone);
    if (emits) add_light(packed, LightKind::triangle, index_of(packed.triangle_shape.size() - 1));
  }
  for (std::uint32_t entry : sphere_bvh.take_primitive_order()) {
    const Sphere& s = spheres[entry];
    packed.sphere_center.push_back(s.center);
    packed.sphere_radius.push_back(s.radius);
    packed.sphere_shape.push_back(s.shape);
    const bool emits = scene.shapes[s.shape].emission.has_value();
    packed.sphere_light.push_back(emits ? index_of(packed.light_kind.size()) : kNone);
    if (emits) add_light(packed, LightKind::sphere, index_of(packed.sphere_shape.size() - 1));
  }

  for (const render::PointLight& light : scene.point_lights) {
    if (light.profile) packed.unsupported.push_back("point light: intensity profile (ignored)");
    add_light(packed, LightKind::point, kNone);
    packed.light_position.back() = light.position;
    packed.light_intensity.back() = light.intensity;
  }
  for (const render::SpotLight& light : scene.spot_lights) {
    add_light(packed, LightKind::spot, kNone);
    packed.light_position.back() = light.position;
    packed.light_intensity.back() = light.intensity;
    packed.light_axis.back() = light.direction;
    packed.light_cos_cone[packed.light_cos_cone.size() - 2] = sg::cos(light.cone_angle);
    packed.light_cos_cone.back() = sg::cos(light.cone_angle - light.cone_delta);
  }
  for (const render::DistantLight& light : scene.distant_lights) {
    add_light(packed, LightKind::distant, kNone);
    packed.light_axis.back() = light.direction;
    packed.light_irradiance.back() = light.irradiance / units::proj;
  }
  if (scene.environment) {
    if (scene.environment->map) packed.unsupported.push_back("environment map (its constant factor is used)");
    packed.frame.environment_light = index_of(packed.light_kind.size());
    packed.frame.environment_radiance = scene.environment->radiance;
    add_light(packed, LightKind::environment, kNone);
  }

  packed.frame.light_count = index_of(packed.light_kind.size());
  packed.frame.max_depth = static_cast<std::uint32_t>(scene.settings.max_depth);
  packed.frame.roulette_depth =
      scene.settings.russian_roulette ? static_cast<std::uint32_t>(scene.settings.russian_roulette_depth) : kNone;
  // Spawned rays start this far off their surface: a relative 1e-5 of the
  // scene's extent, as rounding in float positions needs.
  const Real3 extent = scene_bounds.extent();
  const float largest = std::max({std::abs(scene_bounds.lower.x), std::abs(scene_bounds.lower.y),
                                  std::abs(scene_bounds.lower.z), std::abs(scene_bounds.upper.x),
                                  std::abs(scene_bounds.upper.y), std::abs(scene_bounds.upper.z), extent.x, extent.y,
                                  extent.z});
  packed.frame.ray_offset = sg::from_raw<Length>(1e-5f * std::max(largest, 1.0f));
  // Empty arrays still need one element: a storage buffer is never empty.
  return packed;
}

}  // namespace safegi::gpu
