// A loaded Scene (cpu_renderer's loader) packed into the arrays the path
// tracer's shaders read (gpu_renderer/shaders/scene_buffers.sgl): one typed
// std::vector per storage block, named as the symbol table names the block's
// member, so that the host binds each by name and runtime_vk checks its
// element type, dimension, space and stride against the table.
#pragma once

#include <cstdint>
#include <string_view>
#include <string>
#include <vector>

#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::gpu {

namespace sg = ::safegi;
namespace dim = ::safegi::dim;
namespace units = ::safegi::units;
using render::Scene;

using Length = quantity<dim::length>;
using Radiance = spectrum<dim::radiance>;
using Reflectance = spectrum<dim::dimensionless>;
using Intensity = spectrum<dim::intensity>;
// A distant light's irradiance on the area facing its beam: per projected
// area (scene_buffers.sgl, LightIrradiance).
using NormalIrradiance = spectrum<dim::quotient<dim::irradiance, dim::proj>>;
using PointWorld = point<spaces::world>;
using DirectionWorld = direction<spaces::world>;

inline constexpr std::uint32_t kNone = 0xffffffffu;

// The shaders' enumerations (scene_buffers.sgl).
enum class MaterialKind : std::uint32_t { black = 0, lambert, phong, mirror, glass, plastic };
enum class LightKind : std::uint32_t { point = 0, spot, triangle, sphere, distant, environment };

// The FrameConstants block, member by member, for one image size.
struct FrameValues {
  PointWorld camera_position;
  DirectionWorld camera_forward, camera_right, camera_up;
  Radiance environment_radiance;
  float image_half_width = 0, image_half_height = 0;  // float<1>
  Length ray_offset = sg::zero;
  std::uint32_t image_width = 0, image_height = 0;
  std::uint32_t triangle_root = kNone, sphere_root = kNone;
  std::uint32_t light_count = 0, max_depth = 0, roulette_depth = 0;
  std::uint32_t environment_light = kNone;
  Length lens_radius = sg::zero, focus_distance = sg::zero;
  std::uint32_t environment_width = 0, environment_height = 0;  // 0: a constant sky
  DirectionWorld sky_axis_x{1, 0, 0}, sky_axis_y{0, 1, 0}, sky_axis_z{0, 0, 1};  // the sky's frame
  // Where each dimensionless array starts in PackedScene::number, and the
  // textures' entries in texture_info (scene_buffers.sgl).
  std::uint32_t material_numbers_first = 0, light_cone_first = 0, light_cdf_first = 0;
  std::uint32_t environment_row_cdf_first = 0, environment_column_cdf_first = 0, environment_density_first = 0;
  std::uint32_t triangle_uv_first = 0, texture_mapping_first = 0, texture_info_first = 0;
};

struct PackedScene {
  FrameValues frame;
  // The BVHs: triangle nodes first, then sphere nodes (their interior
  // children renumbered past the triangles').
  std::vector<Length> node_lower, node_upper;           // 12 per node: [4 * axis + child]
  std::vector<std::uint32_t> node_child, node_primitive_count;  // 4 per node
  std::vector<PointWorld> triangle_vertex;              // 3 per triangle, in leaf order
  std::vector<std::uint32_t> triangle_shape, triangle_light;
  std::vector<PointWorld> sphere_center;                // in leaf order
  std::vector<Length> sphere_radius;
  std::vector<std::uint32_t> sphere_shape, sphere_light;
  std::vector<std::uint32_t> shape_material, shape_two_sided;
  std::vector<Radiance> shape_emission;
  std::vector<std::uint32_t> material_kind, material_swapped_fresnel;
  std::vector<Reflectance> material_diffuse, material_specular, material_transmittance;
  std::vector<float> material_exponent, material_alpha, material_ior;  // float<1>
  std::vector<std::uint32_t> light_kind, light_primitive;
  std::vector<PointWorld> light_position;
  std::vector<Intensity> light_intensity;
  std::vector<DirectionWorld> light_axis;
  std::vector<float> light_cos_cone;                    // 2 per light, float<1>
  std::vector<NormalIrradiance> light_irradiance;
  // The running sums of the lights' choice probabilities, in proportion to
  // their power as the CPU renderer's (lights.cpp); the last is exactly 1.
  std::vector<float> light_cdf;                         // float<1>
  // The environment map, when the sky has one (environment.sgl): its texels
  // padded by one all round ((width + 2) × (height + 2), the map's wrap
  // applied), the sky's frame (three world axes), the running sums of the
  // rows' shares and of each row's cells', each cell's density per map area.
  std::vector<Reflectance> environment_texel;
  std::vector<float> environment_row_cdf, environment_column_cdf, environment_density;  // float<1>
  // Image textures (texture.sgl): each triangle's corners' (u, v), 6 per
  // triangle in leaf order; each material's diffuse texture (kNone: none);
  // every texture's texels padded by one all round, where each starts, its
  // size, and its uv mapping (u scale, v scale, u offset, v offset).
  std::vector<float> triangle_uv;                       // float<1>
  std::vector<std::uint32_t> material_texture;
  std::vector<Reflectance> texture_texel;
  std::vector<std::uint32_t> texture_first_texel, texture_width, texture_height, texture_repeats;
  std::vector<float> texture_mapping;                   // float<1>, 4 per texture
  // What the shaders bind: lavapipe allows 32 storage buffers per stage,
  // fewer than the arrays above, so the dimensionless ones (float<1>) share
  // `number` (material_exponent, _alpha, _ior interleaved, light_cos_cone,
  // light_cdf, the environment's sums and densities, triangle_uv,
  // texture_mapping, each from its frame.*_first), the images' texels share
  // `texel` (the environment map's first), and material_texture and each
  // texture's first texel, width and height share `texture_info`.
  std::vector<float> number;
  std::vector<Reflectance> texel;
  std::vector<std::uint32_t> texture_info;
  // What the GPU renderer leaves out of this scene, one line each (textures,
  // media, motion, ...): the program prints them as warnings.
  std::vector<std::string> unsupported;
};

// Packs `scene` for an image of width × height. Throws std::runtime_error
// when the scene has nothing the shaders can draw with.
PackedScene pack_scene(const Scene& scene, int width, int height);

// The running sums of `weights` over their total, the last exactly 1; all-zero
// or non-finite weights give the uniform distribution (as the CPU renderer's
// light_cdf).
std::vector<float> light_cdf(const std::vector<double>& weights);

// Calls visit(name, values) for every storage array, `name` being the block
// member's name in the symbol table ("NodeLower.nodeLower").
template <class Visitor>
void for_each_array(const PackedScene& p, Visitor&& visit) {
  visit(std::string_view("NodeLower.nodeLower"), p.node_lower);
  visit(std::string_view("NodeUpper.nodeUpper"), p.node_upper);
  visit(std::string_view("NodeChild.nodeChild"), p.node_child);
  visit(std::string_view("NodeCount.nodePrimitiveCount"), p.node_primitive_count);
  visit(std::string_view("TriangleVertices.triangleVertex"), p.triangle_vertex);
  visit(std::string_view("TriangleShape.triangleShape"), p.triangle_shape);
  visit(std::string_view("TriangleLight.triangleLight"), p.triangle_light);
  visit(std::string_view("SphereCenter.sphereCenter"), p.sphere_center);
  visit(std::string_view("SphereRadius.sphereRadius"), p.sphere_radius);
  visit(std::string_view("SphereShape.sphereShape"), p.sphere_shape);
  visit(std::string_view("SphereLight.sphereLight"), p.sphere_light);
  visit(std::string_view("ShapeMaterial.shapeMaterial"), p.shape_material);
  visit(std::string_view("ShapeEmission.shapeEmission"), p.shape_emission);
  visit(std::string_view("ShapeTwoSided.shapeTwoSided"), p.shape_two_sided);
  visit(std::string_view("MaterialKind.materialKind"), p.material_kind);
  visit(std::string_view("MaterialDiffuse.materialDiffuse"), p.material_diffuse);
  visit(std::string_view("MaterialSpecular.materialSpecular"), p.material_specular);
  visit(std::string_view("MaterialTransmittance.materialTransmittance"), p.material_transmittance);
  visit(std::string_view("MaterialSwappedFresnel.materialSwappedFresnel"), p.material_swapped_fresnel);
  visit(std::string_view("LightKind.lightKind"), p.light_kind);
  visit(std::string_view("LightPrimitive.lightPrimitive"), p.light_primitive);
  visit(std::string_view("LightPosition.lightPosition"), p.light_position);
  visit(std::string_view("LightIntensity.lightIntensity"), p.light_intensity);
  visit(std::string_view("LightAxis.lightAxis"), p.light_axis);
  visit(std::string_view("LightIrradiance.lightIrradiance"), p.light_irradiance);
  visit(std::string_view("Numbers.number"), p.number);
  visit(std::string_view("Texels.texel"), p.texel);
  visit(std::string_view("TextureInfo.textureInfo"), p.texture_info);
}

}  // namespace safegi::gpu
