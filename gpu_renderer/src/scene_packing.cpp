#include "scene_packing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
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
  std::array<float, 6> uv;  // the corners' (u, v)
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

using Power = quantity<dim::power>;
using Area = quantity<dim::area>;

// What a diffuse emitter of `area` radiates: π·A·L per side (lights.cpp).
Power emitted_power(const Radiance& radiance, Area area, bool two_sided) {
  const Power one_side = sg::average(radiance) * area * (sg::pi * units::steradian * units::proj);
  return two_sided ? 2.0f * one_side : one_side;
}

Area triangle_area(const Triangle& t) {
  const Real3 p0 = kernel_point(t.p0);
  return sg::from_raw<Area>(0.5f * render::kernel::length(render::kernel::cross(kernel_point(t.p1) - p0, kernel_point(t.p2) - p0)));
}

// The scene's image textures (texture.sgl): level 0 of each MIP pyramid,
// padded by one texel with its wrap; its uv mapping, or none (kNone) for the
// mappings the GPU lacks.
std::vector<std::uint32_t> pack_textures(const Scene& scene, PackedScene& packed) {
  std::vector<std::uint32_t> index(scene.textures.size(), kNone);
  for (std::size_t i = 0; i < scene.textures.size(); ++i) {
    const render::ImageTexture& texture = scene.textures[i];
    if (!texture.mipmap) continue;
    if (texture.mapping.kind != render::Mapping2D::Kind::uv) {
      packed.unsupported.push_back("texture '" + texture.name + "': not a uv mapping (its material's constant factor is used)");
      continue;
    }
    const render::MipMap& map = *texture.mipmap;
    const int width = map.width(0), height = map.height(0);
    index[i] = index_of(packed.texture_width.size());
    packed.texture_first_texel.push_back(index_of(packed.texture_texel.size()));
    packed.texture_width.push_back(index_of(static_cast<std::size_t>(width)));
    packed.texture_height.push_back(index_of(static_cast<std::size_t>(height)));
    packed.texture_repeats.push_back(map.wrap() == render::TextureWrap::repeat ? 1u : 0u);
    for (int y = -1; y <= height; ++y)
      for (int x = -1; x <= width; ++x) packed.texture_texel.push_back(map.texel(0, x, y));
    packed.texture_mapping.insert(packed.texture_mapping.end(), {texture.mapping.u_scale, texture.mapping.v_scale,
                                                                 texture.mapping.u_offset, texture.mapping.v_offset});
  }
  return index;
}

void pack_materials(const Scene& scene, PackedScene& packed) {
  const std::vector<std::uint32_t> texture_index = pack_textures(scene, packed);
  for (const render::Material& material : scene.materials) {
    std::uint32_t texture = kNone;
    MaterialKind kind = MaterialKind::black;
    Reflectance diffuse{}, specular{}, transmittance{};
    float exponent = 1, alpha = 0, ior = 1.5f;
    bool swapped = false;
    auto note_texture = [&](const render::TexturedReflectance& r) {
      if (r.texture >= 0 && texture_index[static_cast<std::size_t>(r.texture)] != kNone)
        texture = texture_index[static_cast<std::size_t>(r.texture)];
      else if (r.textured())
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
    packed.material_texture.push_back(kind == MaterialKind::black ? kNone : texture);
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

// The environment map (environment.sgl): texels padded by one with the map's
// wrap, the sky's axes, and the piecewise-constant distribution the CPU
// renderer's Environment draws from (each cell weighted by the luminance of
// its 3 × 3 neighbourhood times sin θ, the map's area stretch). Returns the
// sky's mean radiance over the sphere (for choosing lights by power).
Radiance pack_environment_map(const render::EnvironmentLight& light, PackedScene& packed) {
  const render::MipMap& map = *light.map;
  const int width = map.width(0), height = map.height(0);
  packed.frame.environment_width = index_of(static_cast<std::size_t>(width));
  packed.frame.environment_height = index_of(static_cast<std::size_t>(height));
  for (int y = -1; y <= height; ++y)
    for (int x = -1; x <= width; ++x) packed.environment_texel.push_back(map.texel(0, x, y));
  packed.frame.sky_axis_x = light.render_from_light(direction<spaces::light>(1, 0, 0));
  packed.frame.sky_axis_y = light.render_from_light(direction<spaces::light>(0, 1, 0));
  packed.frame.sky_axis_z = light.render_from_light(direction<spaces::light>(0, 0, 1));
  std::vector<double> weights(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  std::vector<double> row_sums(static_cast<std::size_t>(height));
  Reflectance texel_sum{};
  double sin_sum = 0, total = 0;
  for (int y = 0; y < height; ++y) {
    const double sin_theta = std::sin(3.14159265358979 * (y + 0.5) / height);
    for (int x = 0; x < width; ++x) {
      double sum = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) sum += sg::raw(sg::luminance(map.texel(0, x + dx, y + dy)));
      const double w = sum / 9 * sin_theta;
      weights[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)] = w;
      row_sums[static_cast<std::size_t>(y)] += w;
      total += w;
      texel_sum += map.texel(0, x, y) * static_cast<float>(sin_theta);
    }
    sin_sum += sin_theta * width;
  }
  packed.environment_row_cdf = light_cdf(row_sums);
  const double cells = static_cast<double>(width) * height;
  for (int y = 0; y < height; ++y) {
    const auto first = weights.begin() + static_cast<std::ptrdiff_t>(y) * width;
    const std::vector<float> row = light_cdf(std::vector<double>(first, first + width));
    packed.environment_column_cdf.insert(packed.environment_column_cdf.end(), row.begin(), row.end());
  }
  for (double w : weights)
    packed.environment_density.push_back(static_cast<float>(total > 0 ? w / total * cells : 1.0));
  return light.radiance * (texel_sum / static_cast<float>(sin_sum));
}

// The arrays that share a buffer (PackedScene::number, texel, texture_info),
// each from its offset.
void pack_shared_arrays(PackedScene& packed) {
  FrameValues& frame = packed.frame;
  std::vector<float>& number = packed.number;
  auto append = [&](std::uint32_t& first, const std::vector<float>& values) {
    first = index_of(number.size());
    number.insert(number.end(), values.begin(), values.end());
  };
  frame.material_numbers_first = index_of(number.size());
  for (std::size_t m = 0; m < packed.material_exponent.size(); ++m)
    number.insert(number.end(), {packed.material_exponent[m], packed.material_alpha[m], packed.material_ior[m]});
  append(frame.light_cone_first, packed.light_cos_cone);
  append(frame.light_cdf_first, packed.light_cdf);
  append(frame.environment_row_cdf_first, packed.environment_row_cdf);
  append(frame.environment_column_cdf_first, packed.environment_column_cdf);
  append(frame.environment_density_first, packed.environment_density);
  append(frame.triangle_uv_first, packed.triangle_uv);
  append(frame.texture_mapping_first, packed.texture_mapping);
  packed.texel = packed.environment_texel;
  packed.texel.insert(packed.texel.end(), packed.texture_texel.begin(), packed.texture_texel.end());
  packed.texture_info = packed.material_texture;
  frame.texture_info_first = index_of(packed.texture_info.size());
  for (std::size_t t = 0; t < packed.texture_width.size(); ++t)
    packed.texture_info.insert(packed.texture_info.end(),
                               {index_of(packed.environment_texel.size()) + packed.texture_first_texel[t],
                                packed.texture_width[t], packed.texture_height[t], packed.texture_repeats[t]});
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
    // A triangle's corners' (u, v): the shape's, or (0, 0), (1, 0), (1, 1) (as the CPU renderer's vertex_uv).
    for (std::size_t i = 0; i + 2 < shape.indices.size(); i += 3) {
      std::array<float, 6> uv{0, 0, 1, 0, 1, 1};
      if (!shape.uvs.empty())
        for (std::size_t k = 0; k < 3; ++k) {
          uv[2 * k] = shape.uvs[shape.indices[i + k]].u;
          uv[2 * k + 1] = shape.uvs[shape.indices[i + k]].v;
        }
      triangles.push_back({shape.render_from_object(shape.positions[shape.indices[i]]),
                           shape.render_from_object(shape.positions[shape.indices[i + 1]]),
                           shape.render_from_object(shape.positions[shape.indices[i + 2]]), index_of(s), uv});
    }
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
  // Each light's power (watts, averaged over the channels) for choosing
  // lights in proportion to it, defined per kind as the CPU renderer's
  // Lights (lights.cpp): an emitting triangle's is its share of its shape's.
  std::vector<double> powers;
  for (std::uint32_t entry : triangle_bvh.take_primitive_order()) {
    const Triangle& t = triangles[entry];
    packed.triangle_vertex.insert(packed.triangle_vertex.end(), {t.p0, t.p1, t.p2});
    packed.triangle_shape.push_back(t.shape);
    packed.triangle_uv.insert(packed.triangle_uv.end(), t.uv.begin(), t.uv.end());
    const bool emits = scene.shapes[t.shape].emission.has_value();
    packed.triangle_light.push_back(emits ? index_of(packed.light_kind.size()) : kNone);
    if (emits) {
      add_light(packed, LightKind::triangle, index_of(packed.triangle_shape.size() - 1));
      const render::Shape& shape = scene.shapes[t.shape];
      powers.push_back(sg::raw(emitted_power(*shape.emission, triangle_area(t), shape.two_sided_emission)));
    }
  }
  for (std::uint32_t entry : sphere_bvh.take_primitive_order()) {
    const Sphere& s = spheres[entry];
    packed.sphere_center.push_back(s.center);
    packed.sphere_radius.push_back(s.radius);
    packed.sphere_shape.push_back(s.shape);
    const bool emits = scene.shapes[s.shape].emission.has_value();
    packed.sphere_light.push_back(emits ? index_of(packed.light_kind.size()) : kNone);
    if (emits) {
      add_light(packed, LightKind::sphere, index_of(packed.sphere_shape.size() - 1));
      const render::Shape& shape = scene.shapes[s.shape];
      const Area area = 4 * sg::pi * s.radius * s.radius;
      powers.push_back(sg::raw(emitted_power(*shape.emission, area, shape.two_sided_emission)));
    }
  }

  for (const render::PointLight& light : scene.point_lights) {
    if (light.profile) packed.unsupported.push_back("point light: intensity profile (ignored)");
    add_light(packed, LightKind::point, kNone);
    packed.light_position.back() = light.position;
    packed.light_intensity.back() = light.intensity;
    powers.push_back(sg::raw(sg::average(light.intensity) * (4 * sg::pi * units::steradian)));
  }
  for (const render::SpotLight& light : scene.spot_lights) {
    add_light(packed, LightKind::spot, kNone);
    packed.light_position.back() = light.position;
    packed.light_intensity.back() = light.intensity;
    packed.light_axis.back() = light.direction;
    packed.light_cos_cone[packed.light_cos_cone.size() - 2] = sg::cos(light.cone_angle);
    packed.light_cos_cone.back() = sg::cos(light.cone_angle - light.cone_delta);
    // pbrt-v3's SpotLight::Power: the full cone at I, the falloff band at half.
    const float cos_total = sg::cos(light.cone_angle), cos_start = sg::cos(light.cone_angle - light.cone_delta);
    const auto cone = (2 * sg::pi * (1 - 0.5f * (cos_start + cos_total))) * units::steradian;
    powers.push_back(sg::raw(sg::average(light.intensity) * cone));
  }
  // The scene's bounding sphere, for the distant lights' and the sky's power.
  const Length scene_radius = sg::from_raw<Length>(std::max(0.5f * render::kernel::length(scene_bounds.extent()),
                                                            std::numeric_limits<float>::min()));
  for (const render::DistantLight& light : scene.distant_lights) {
    add_light(packed, LightKind::distant, kNone);
    packed.light_axis.back() = light.direction;
    packed.light_irradiance.back() = light.irradiance / units::proj;
    // pbrt-v3's DistantLight::Power: the flux through a disc across the scene's bounding sphere.
    powers.push_back(sg::raw(sg::average(light.irradiance) * (sg::pi * scene_radius * scene_radius)));
  }
  if (scene.environment) {
    packed.frame.environment_light = index_of(packed.light_kind.size());
    packed.frame.environment_radiance = scene.environment->radiance;
    add_light(packed, LightKind::environment, kNone);
    const Radiance average =
        scene.environment->map ? pack_environment_map(*scene.environment, packed) : scene.environment->radiance;
    // The flux it sends into the scene's bounding sphere, π · L̄ · 4πr².
    const Area sphere = 4 * sg::pi * scene_radius * scene_radius;
    powers.push_back(sg::raw(sg::average(average) * sphere *
                             (sg::pi * units::steradian * units::proj)));
  }

  packed.frame.light_count = index_of(packed.light_kind.size());
  packed.light_cdf = light_cdf(powers);
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
  pack_shared_arrays(packed);
  // Empty arrays still need one element: a storage buffer is never empty.
  return packed;
}

std::vector<float> light_cdf(const std::vector<double>& weights) {
  double total = 0;
  for (double w : weights) total += w;
  const bool uniform = !(total > 0) || !std::isfinite(total);
  std::vector<float> cdf;
  cdf.reserve(weights.size());
  double running = 0;
  for (double w : weights) {
    running += uniform ? 1.0 / static_cast<double>(weights.size()) : w / total;
    cdf.push_back(static_cast<float>(running));
  }
  if (!cdf.empty()) cdf.back() = 1;
  return cdf;
}

}  // namespace safegi::gpu
