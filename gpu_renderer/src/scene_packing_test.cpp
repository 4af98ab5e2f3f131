// Every array pack_scene makes against the symbol table safeglslc wrote for
// the shaders: the block exists at its binding, the member is what the host
// wrote (kind, dimension exponents, space) and the host's element size is
// the table's std430 array stride. runtime_vk checks the same when it binds;
// this test keeps the packing honest without a Vulkan device.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <type_traits>

#include "safegi/cpu_renderer/scene_loader.hpp"
#include "safegi/typed/reflection.hpp"
#include "scene_packing.hpp"

namespace safegi::gpu {
namespace {

using nlohmann::json;

json read_symbols() {
  std::ifstream in(SAFEGI_GPU_SYMBOLS);
  EXPECT_TRUE(in) << SAFEGI_GPU_SYMBOLS;
  return json::parse(in);
}

// The member "Block.member" of the compute stage's storage blocks, or null.
const json* find_member(const json& symbols, std::string_view name) {
  const auto dot = name.find('.');
  const std::string block(name.substr(0, dot)), member(name.substr(dot + 1));
  for (const json& symbol : symbols["stages"][0]["symbols"])
    if (symbol.value("name", "") == block && symbol.value("storage", "") == "buffer")
      for (const json& m : symbol["members"])
        if (m["name"] == member) return &m;
  return nullptr;
}

// What the table says for a C++ element type T: its kind word, std430 stride,
// dimension exponents (base name -> exponent) and space.
struct Expected {
  std::string kind;
  std::uint32_t stride;
  std::map<std::string, int> exponents;
  std::string space;
};

template <class T>
Expected expected_for() {
  Expected e;
  if constexpr (std::is_same_v<T, std::uint32_t>) {
    return {"plain", 4, {}, ""};
  } else if constexpr (std::is_same_v<T, float>) {
    return {"scalar", 4, {}, ""};  // float<1>: a dimensionless quantity
  } else {
    const type_description d = describe<T>();
    e.kind = d.kind == type_kind::scalar ? "scalar" : std::string(to_string(d.kind));
    e.stride = d.kind == type_kind::scalar ? 4 : 16;  // a vec3 in std430 arrays takes 16 bytes
    for (const dimension_term& term : d.dimension) e.exponents[std::string(term.base)] = term.exponent;
    e.space = std::string(d.space);
    // Points, directions and normals are lengths and ratios by their kind: the table gives no dimension.
    if (d.kind == type_kind::point || d.kind == type_kind::direction || d.kind == type_kind::normal) e.exponents.clear();
    return e;
  }
}

render::Scene load(const std::string& name) { return render::load_scene(std::string(SAFEGI_SCENES_DIR) + "/" + name); }

void expect_matches_table(const PackedScene& packed) {
  const json symbols = read_symbols();
  int arrays = 0;
  for_each_array(packed, [&](std::string_view name, const auto& values) {
    using T = typename std::decay_t<decltype(values)>::value_type;
    ++arrays;
    SCOPED_TRACE(std::string(name));
    const json* member = find_member(symbols, name);
    ASSERT_NE(member, nullptr) << "no storage block member " << name << " in the shaders' symbol table";
    const Expected e = expected_for<T>();
    EXPECT_EQ((*member)["kind"], e.kind);
    EXPECT_EQ((*member)["array_stride"], e.stride);
    EXPECT_TRUE(member->value("unsized", false));
    std::map<std::string, int> exponents;
    if (member->contains("dimension"))
      for (const auto& [base, exponent] : (*member)["dimension"]["exponents"].items()) exponents[base] = exponent;
    EXPECT_EQ(exponents, e.exponents);
    const std::string space = member->contains("spaces") ? (*member)["spaces"][0].get<std::string>() : "";
    EXPECT_EQ(space, e.space);
  });
  EXPECT_EQ(arrays, 28);
}

TEST(ScenePacking, CornellBoxArraysMatchTheSymbolTable) {
  const render::Scene scene = load("cornell-box/cornell-box.json");
  const PackedScene packed = pack_scene(scene, 64, 64);
  expect_matches_table(packed);
  // One entry per material and shape, each material Lambert.
  ASSERT_EQ(packed.material_kind.size(), scene.materials.size());
  EXPECT_EQ(packed.material_diffuse.size(), scene.materials.size());
  EXPECT_EQ(packed.shape_material.size(), scene.shapes.size());
  for (std::uint32_t kind : packed.material_kind) EXPECT_EQ(kind, static_cast<std::uint32_t>(MaterialKind::lambert));
  // The BVH as built: 12 slab planes and 4 children per node.
  EXPECT_EQ(packed.node_lower.size() % 12, 0u);
  EXPECT_EQ(packed.node_child.size() * 3, packed.node_lower.size());
  EXPECT_EQ(packed.triangle_vertex.size(), 3 * packed.triangle_shape.size());
  EXPECT_EQ(packed.frame.sphere_root, kNone);
  // The light's two triangles are its only lights.
  EXPECT_EQ(packed.frame.light_count, 2u);
  EXPECT_TRUE(packed.unsupported.empty());
}

TEST(ScenePacking, EveryLeafPrimitiveIsPackedOnce) {
  const PackedScene packed = pack_scene(load("phong.json"), 40, 16);
  std::vector<int> seen_triangles(packed.triangle_shape.size()), seen_spheres(packed.sphere_shape.size());
  const std::uint32_t sphere_root = packed.frame.sphere_root;
  for (std::size_t slot = 0; slot < packed.node_child.size(); ++slot) {
    const std::uint32_t count = packed.node_primitive_count[slot];
    if (count == 0) continue;
    const bool sphere_node = sphere_root != kNone && slot / 4 >= sphere_root;
    for (std::uint32_t k = 0; k < count; ++k) ++(sphere_node ? seen_spheres : seen_triangles)[packed.node_child[slot] + k];
  }
  for (int n : seen_triangles) EXPECT_EQ(n, 1);
  for (int n : seen_spheres) EXPECT_EQ(n, 1);
  EXPECT_GT(seen_spheres.size(), 0u);
}

// textured-floor.json's floor: an image texture, level 0 padded by one, its
// uv mapping, repeating; each triangle has its corners' (u, v).
TEST(ScenePacking, ImageTexturesArePacked) {
  const render::Scene scene = render::load_scene(std::string(SAFEGI_GPU_TESTDATA) + "/textured-floor.json");
  const PackedScene packed = pack_scene(scene, 32, 24);
  ASSERT_EQ(packed.texture_width.size(), 1u);
  EXPECT_EQ(packed.texture_width[0], 16u);
  EXPECT_EQ(packed.texture_height[0], 8u);
  EXPECT_EQ(packed.texture_texel.size(), (16u + 2) * (8u + 2));
  EXPECT_EQ(packed.texture_mapping, (std::vector<float>{1, 2, 0.1f, 0}));
  EXPECT_EQ(packed.texture_repeats, (std::vector<std::uint32_t>{1}));
  EXPECT_EQ(std::count(packed.material_texture.begin(), packed.material_texture.end(), 0u), 1);
  EXPECT_EQ(packed.triangle_uv.size(), 6 * packed.triangle_shape.size());
  for (const std::string& line : packed.unsupported) EXPECT_EQ(line.find("texture"), std::string::npos) << line;
}

TEST(ScenePacking, LightsOfEveryKind) {
  const PackedScene environment = pack_scene(load("environment.json"), 32, 20);
  ASSERT_NE(environment.frame.environment_light, kNone);
  EXPECT_EQ(environment.light_kind[environment.frame.environment_light],
            static_cast<std::uint32_t>(LightKind::environment));
  // Its map: padded texels, three axes, a distribution whose densities per
  // map area average 1 (the map square has area 1).
  const std::size_t width = environment.frame.environment_width, height = environment.frame.environment_height;
  ASSERT_GT(width * height, 0u);
  EXPECT_EQ(environment.environment_texel.size(), (width + 2) * (height + 2));
  ASSERT_EQ(environment.environment_row_cdf.size(), height);
  ASSERT_EQ(environment.environment_column_cdf.size(), width * height);
  EXPECT_EQ(environment.environment_row_cdf.back(), 1.0f);
  double density_sum = 0;
  for (float d : environment.environment_density) density_sum += d;
  EXPECT_NEAR(density_sum / static_cast<double>(width * height), 1.0, 1e-4);
  EXPECT_TRUE(environment.unsupported.empty() ||
              std::none_of(environment.unsupported.begin(), environment.unsupported.end(),
                           [](const std::string& s) { return s.find("environment map") != std::string::npos; }));
  const PackedScene phong = pack_scene(load("phong.json"), 40, 16);
  EXPECT_EQ(std::count(phong.light_kind.begin(), phong.light_kind.end(), static_cast<std::uint32_t>(LightKind::point)), 1);
}

// Lights are chosen in proportion to their power (as the CPU renderer's
// Lights): the running sums end at 1, and two point lights' probabilities
// are in the ratio of their mean intensities.
TEST(ScenePacking, LightsAreChosenInProportionToPower) {
  EXPECT_EQ(light_cdf({1, 3}), (std::vector<float>{0.25f, 1.0f}));
  EXPECT_EQ(light_cdf({0, 0}), (std::vector<float>{0.5f, 1.0f}));
  const render::Scene scene = load("many-lights.json");
  const PackedScene packed = pack_scene(scene, 32, 20);
  ASSERT_EQ(packed.light_cdf.size(), packed.frame.light_count);
  EXPECT_EQ(packed.light_cdf.back(), 1.0f);
  EXPECT_TRUE(std::is_sorted(packed.light_cdf.begin(), packed.light_cdf.end()));
  auto probability = [&](std::size_t i) { return i == 0 ? packed.light_cdf[0] : packed.light_cdf[i] - packed.light_cdf[i - 1]; };
  const auto first_point = static_cast<std::size_t>(
      std::find(packed.light_kind.begin(), packed.light_kind.end(), static_cast<std::uint32_t>(LightKind::point)) -
      packed.light_kind.begin());
  ASSERT_GE(scene.point_lights.size(), 2u);
  ASSERT_LE(first_point + scene.point_lights.size(), packed.light_cdf.size());
  const double intensity0 = sg::raw(sg::average(scene.point_lights[0].intensity));
  for (std::size_t k = 1; k < scene.point_lights.size(); ++k) {
    const double ratio = sg::raw(sg::average(scene.point_lights[k].intensity)) / intensity0;
    EXPECT_NEAR(probability(first_point + k) / probability(first_point), ratio, 1e-3 * ratio) << "point light " << k;
  }
  // The Cornell box's light: two triangles of one area, one half each.
  const PackedScene box = pack_scene(load("cornell-box/cornell-box.json"), 16, 16);
  ASSERT_EQ(box.light_cdf.size(), 2u);
  EXPECT_NEAR(box.light_cdf[0], 0.5f, 1e-5f);
}

}  // namespace
}  // namespace safegi::gpu
