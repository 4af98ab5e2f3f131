#include <safegi/lexer/extensions.hpp>

#include <algorithm>
#include <array>
#include <iterator>
#include <utility>

#include <safegi/lexer/token.hpp>

namespace safegi {
namespace {

constexpr std::uint32_t bit(ExtensionGroup g) { return 1u << static_cast<unsigned>(g); }

using G = ExtensionGroup;
constexpr std::uint32_t kLayout = bit(G::layout);
constexpr std::uint32_t kImages = bit(G::image_load_store) | bit(G::memory_qualifiers);
constexpr std::uint32_t kArithmetic = bit(G::arithmetic_types);

// Extensions of desktop GLSL up to 4.60 and of ESSL up to 3.20 (and a few
// vendor ones in wide use) whose additions are syntax this front end parses:
// keywords (their group), layout identifiers, built-in functions and
// variables, directives. Sorted by name. Extensions that add syntax the
// parser does not know are left out, so `#ifdef` on them says "not
// supported", as it should.
constexpr std::array kExtensions = {
    ExtensionInfo{"GL_AMD_conservative_depth", kLayout},
    ExtensionInfo{"GL_AMD_gpu_shader_half_float", kArithmetic},
    ExtensionInfo{"GL_AMD_gpu_shader_half_float_fetch", bit(G::half_float_fetch) | kArithmetic},
    ExtensionInfo{"GL_AMD_gpu_shader_int16", kArithmetic},
    ExtensionInfo{"GL_AMD_shader_stencil_export", 0},
    ExtensionInfo{"GL_AMD_shader_trinary_minmax", 0},
    ExtensionInfo{"GL_AMD_vertex_shader_layer", 0},
    ExtensionInfo{"GL_AMD_vertex_shader_viewport_index", 0},
    ExtensionInfo{"GL_ARB_arrays_of_arrays", 0},
    ExtensionInfo{"GL_ARB_bindless_texture", kLayout},
    ExtensionInfo{"GL_ARB_compute_shader", kLayout},
    ExtensionInfo{"GL_ARB_compute_variable_group_size", kLayout},
    ExtensionInfo{"GL_ARB_conservative_depth", kLayout},
    ExtensionInfo{"GL_ARB_cull_distance", 0},
    ExtensionInfo{"GL_ARB_derivative_control", 0},
    ExtensionInfo{"GL_ARB_draw_buffers", 0},
    ExtensionInfo{"GL_ARB_draw_instanced", 0},
    ExtensionInfo{"GL_ARB_enhanced_layouts", kLayout},
    ExtensionInfo{"GL_ARB_explicit_attrib_location", kLayout},
    ExtensionInfo{"GL_ARB_explicit_uniform_location", kLayout},
    ExtensionInfo{"GL_ARB_fragment_coord_conventions", kLayout},
    ExtensionInfo{"GL_ARB_fragment_layer_viewport", 0},
    ExtensionInfo{"GL_ARB_fragment_shader_interlock", kLayout},
    ExtensionInfo{"GL_ARB_geometry_shader4", 0},
    ExtensionInfo{"GL_ARB_gpu_shader5", bit(G::gpu_shader5)},
    ExtensionInfo{"GL_ARB_gpu_shader_fp64", bit(G::fp64)},
    ExtensionInfo{"GL_ARB_gpu_shader_int64", kArithmetic},
    ExtensionInfo{"GL_ARB_post_depth_coverage", kLayout},
    ExtensionInfo{"GL_ARB_sample_shading", 0},
    ExtensionInfo{"GL_ARB_separate_shader_objects", kLayout},
    ExtensionInfo{"GL_ARB_shader_atomic_counter_ops", 0},
    ExtensionInfo{"GL_ARB_shader_atomic_counters", bit(G::atomic_counters)},
    ExtensionInfo{"GL_ARB_shader_ballot", 0},
    ExtensionInfo{"GL_ARB_shader_bit_encoding", 0},
    ExtensionInfo{"GL_ARB_shader_clock", 0},
    ExtensionInfo{"GL_ARB_shader_draw_parameters", 0},
    ExtensionInfo{"GL_ARB_shader_group_vote", 0},
    ExtensionInfo{"GL_ARB_shader_image_load_store", kImages},
    ExtensionInfo{"GL_ARB_shader_image_size", 0},
    ExtensionInfo{"GL_ARB_shader_precision", 0},
    ExtensionInfo{"GL_ARB_shader_stencil_export", 0},
    // Buffer variables take the memory qualifiers (coherent, readonly, ...).
    ExtensionInfo{"GL_ARB_shader_storage_buffer_object", bit(G::storage_buffer) | bit(G::memory_qualifiers)},
    ExtensionInfo{"GL_ARB_shader_subroutine", bit(G::subroutine)},
    ExtensionInfo{"GL_ARB_shader_texture_image_samples", 0},
    ExtensionInfo{"GL_ARB_shader_texture_lod", 0},
    ExtensionInfo{"GL_ARB_shader_viewport_layer_array", 0},
    ExtensionInfo{"GL_ARB_shading_language_420pack", kLayout},
    ExtensionInfo{"GL_ARB_shading_language_packing", 0},
    ExtensionInfo{"GL_ARB_sparse_texture2", 0},
    ExtensionInfo{"GL_ARB_sparse_texture_clamp", 0},
    ExtensionInfo{"GL_ARB_tessellation_shader", bit(G::tessellation)},
    ExtensionInfo{"GL_ARB_texture_buffer_object", bit(G::texture_buffer)},
    ExtensionInfo{"GL_ARB_texture_cube_map_array", bit(G::cube_map_array)},
    ExtensionInfo{"GL_ARB_texture_gather", 0},
    ExtensionInfo{"GL_ARB_texture_multisample", bit(G::multisample)},
    ExtensionInfo{"GL_ARB_texture_query_levels", 0},
    ExtensionInfo{"GL_ARB_texture_query_lod", 0},
    ExtensionInfo{"GL_ARB_texture_rectangle", bit(G::texture_rectangle)},
    ExtensionInfo{"GL_ARB_uniform_buffer_object", kLayout},
    ExtensionInfo{"GL_ARB_vertex_attrib_64bit", bit(G::fp64)},
    ExtensionInfo{"GL_ARB_viewport_array", 0},
    ExtensionInfo{"GL_EXT_blend_func_extended", 0},
    ExtensionInfo{"GL_EXT_buffer_reference", 0},
    ExtensionInfo{"GL_EXT_buffer_reference2", 0},
    ExtensionInfo{"GL_EXT_buffer_reference_uvec2", 0},
    ExtensionInfo{"GL_EXT_conservative_depth", kLayout},
    ExtensionInfo{"GL_EXT_control_flow_attributes", 0},
    ExtensionInfo{"GL_EXT_debug_printf", 0},
    ExtensionInfo{"GL_EXT_device_group", 0},
    ExtensionInfo{"GL_EXT_draw_instanced", 0},
    ExtensionInfo{"GL_EXT_frag_depth", 0},
    ExtensionInfo{"GL_EXT_fragment_shader_barycentric", bit(G::barycentric)},
    ExtensionInfo{"GL_EXT_geometry_shader", 0},
    // flat / noperspective varyings, unsigned integers and samplerBuffer at GLSL 1.10 and 1.20.
    ExtensionInfo{"GL_EXT_gpu_shader4",
                  bit(G::interpolation) | bit(G::unsigned_integers) | bit(G::texture_buffer)},
    ExtensionInfo{"GL_EXT_gpu_shader5", bit(G::gpu_shader5)},
    ExtensionInfo{"GL_EXT_mesh_shader", bit(G::mesh_shading)},
    ExtensionInfo{"GL_EXT_multiview", 0},
    ExtensionInfo{"GL_EXT_nonuniform_qualifier", bit(G::nonuniform)},
    ExtensionInfo{"GL_EXT_null_initializer", 0},
    ExtensionInfo{"GL_EXT_primitive_bounding_box", 0},
    ExtensionInfo{"GL_EXT_ray_cull_mask", 0},
    ExtensionInfo{"GL_EXT_ray_flags_primitive_culling", 0},
    ExtensionInfo{"GL_EXT_ray_query", 0},
    ExtensionInfo{"GL_EXT_ray_tracing", bit(G::ray_tracing)},
    ExtensionInfo{"GL_EXT_ray_tracing_position_fetch", 0},
    ExtensionInfo{"GL_EXT_samplerless_texture_functions", 0},
    ExtensionInfo{"GL_EXT_scalar_block_layout", kLayout},
    ExtensionInfo{"GL_EXT_separate_shader_objects", kLayout},
    ExtensionInfo{"GL_EXT_shader_16bit_storage", kArithmetic},
    ExtensionInfo{"GL_EXT_shader_8bit_storage", kArithmetic},
    ExtensionInfo{"GL_EXT_shader_atomic_float", 0},
    ExtensionInfo{"GL_EXT_shader_atomic_int64", 0},
    ExtensionInfo{"GL_EXT_shader_explicit_arithmetic_types", kArithmetic},
    ExtensionInfo{"GL_EXT_shader_explicit_arithmetic_types_float16", kArithmetic},
    ExtensionInfo{"GL_EXT_shader_explicit_arithmetic_types_float32", kArithmetic},
    ExtensionInfo{"GL_EXT_shader_explicit_arithmetic_types_float64", kArithmetic},
    ExtensionInfo{"GL_EXT_shader_explicit_arithmetic_types_int16", kArithmetic},
    ExtensionInfo{"GL_EXT_shader_explicit_arithmetic_types_int32", kArithmetic},
    ExtensionInfo{"GL_EXT_shader_explicit_arithmetic_types_int64", kArithmetic},
    ExtensionInfo{"GL_EXT_shader_explicit_arithmetic_types_int8", kArithmetic},
    ExtensionInfo{"GL_EXT_shader_image_int64", bit(G::image_int64)},
    ExtensionInfo{"GL_EXT_shader_image_load_store", kImages},
    ExtensionInfo{"GL_EXT_shader_integer_mix", 0},
    ExtensionInfo{"GL_EXT_shader_io_blocks", 0},
    ExtensionInfo{"GL_EXT_shader_realtime_clock", 0},
    ExtensionInfo{"GL_EXT_shader_subgroup_extended_types_float16", kArithmetic},
    ExtensionInfo{"GL_EXT_shader_subgroup_extended_types_int16", kArithmetic},
    ExtensionInfo{"GL_EXT_shader_subgroup_extended_types_int64", kArithmetic},
    ExtensionInfo{"GL_EXT_shader_subgroup_extended_types_int8", kArithmetic},
    ExtensionInfo{"GL_EXT_shader_texture_lod", 0},
    ExtensionInfo{"GL_EXT_spirv_intrinsics", 0},
    ExtensionInfo{"GL_EXT_tessellation_shader", bit(G::tessellation)},
    ExtensionInfo{"GL_EXT_texture_array", bit(G::texture_array)},
    ExtensionInfo{"GL_EXT_texture_buffer", bit(G::texture_buffer)},
    ExtensionInfo{"GL_EXT_texture_cube_map_array", bit(G::cube_map_array)},
    ExtensionInfo{"GL_GOOGLE_cpp_style_line_directive", 0},
    ExtensionInfo{"GL_GOOGLE_include_directive", 0},
    ExtensionInfo{"GL_KHR_memory_scope_semantics", 0},
    ExtensionInfo{"GL_KHR_shader_subgroup_arithmetic", 0},
    ExtensionInfo{"GL_KHR_shader_subgroup_ballot", 0},
    ExtensionInfo{"GL_KHR_shader_subgroup_basic", 0},
    ExtensionInfo{"GL_KHR_shader_subgroup_clustered", 0},
    ExtensionInfo{"GL_KHR_shader_subgroup_quad", 0},
    ExtensionInfo{"GL_KHR_shader_subgroup_shuffle", 0},
    ExtensionInfo{"GL_KHR_shader_subgroup_shuffle_relative", 0},
    ExtensionInfo{"GL_KHR_shader_subgroup_vote", 0},
    ExtensionInfo{"GL_MESA_shader_integer_functions", 0},
    ExtensionInfo{"GL_NV_fragment_shader_barycentric", bit(G::barycentric)},
    ExtensionInfo{"GL_NV_gpu_shader5", bit(G::gpu_shader5) | kArithmetic},
    ExtensionInfo{"GL_NV_mesh_shader", bit(G::mesh_shading)},
    ExtensionInfo{"GL_NV_ray_tracing", bit(G::ray_tracing)},
    ExtensionInfo{"GL_NV_shader_noperspective_interpolation", bit(G::interpolation)},
    ExtensionInfo{"GL_OES_EGL_image_external", bit(G::external_image)},
    ExtensionInfo{"GL_OES_EGL_image_external_essl3", bit(G::external_image)},
    ExtensionInfo{"GL_OES_geometry_point_size", 0},
    ExtensionInfo{"GL_OES_geometry_shader", 0},
    ExtensionInfo{"GL_OES_gpu_shader5", bit(G::gpu_shader5)},
    ExtensionInfo{"GL_OES_primitive_bounding_box", 0},
    ExtensionInfo{"GL_OES_sample_variables", 0},
    ExtensionInfo{"GL_OES_shader_image_atomic", 0},
    ExtensionInfo{"GL_OES_shader_io_blocks", 0},
    ExtensionInfo{"GL_OES_shader_multisample_interpolation", bit(G::gpu_shader5)},
    ExtensionInfo{"GL_OES_standard_derivatives", 0},
    ExtensionInfo{"GL_OES_tessellation_point_size", 0},
    ExtensionInfo{"GL_OES_tessellation_shader", bit(G::tessellation)},
    ExtensionInfo{"GL_OES_texture_3D", 0},
    ExtensionInfo{"GL_OES_texture_buffer", bit(G::texture_buffer)},
    ExtensionInfo{"GL_OES_texture_cube_map_array", bit(G::cube_map_array)},
    ExtensionInfo{"GL_OES_texture_storage_multisample_2d_array", bit(G::multisample)},
    ExtensionInfo{"GL_OES_viewport_array", 0},
};

constexpr ExtensionInfo kVulkanGlsl{kVulkanGlslExtension, bit(G::vulkan)};

struct FeatureGate {
  LanguageFeature feature;
  std::string_view what;  // the subject of "... require(s) #version N"
  bool plural;
  int desktop_since;
  int es_since;                 // 0: never in ES
  std::array<std::string_view, 6> extensions;  // any of these enables it (desktop and ES)
  std::size_t named = 1;  // how many of them the message names (the main one first)
};

constexpr std::array kFeatureGates = {
    FeatureGate{LanguageFeature::double_literals, "double-precision literals ('lf' suffix)", true, 400, 0,
                {"GL_ARB_gpu_shader_fp64", "GL_NV_gpu_shader5", "GL_EXT_shader_explicit_arithmetic_types_float64"}},
    // Geometry-shader inputs of arrays (`varying in float v[][6]`) predate GL_ARB_arrays_of_arrays.
    FeatureGate{LanguageFeature::arrays_of_arrays, "arrays of arrays", true, 430, 310,
                {"GL_ARB_arrays_of_arrays", "GL_ARB_geometry_shader4", "GL_EXT_geometry_shader4"}},
    // `varying out` fragment outputs (gpu_shader4), `varying in` geometry
    // inputs, and the extensions whose layouts qualify `in` / `out` (piglit
    // expects them to work in GLSL 1.10).
    FeatureGate{LanguageFeature::global_in_out, "'in' and 'out' on global variables", true, 130, 300,
                {"GL_EXT_gpu_shader4", "GL_ARB_geometry_shader4", "GL_EXT_geometry_shader4",
                 "GL_ARB_explicit_attrib_location", "GL_ARB_separate_shader_objects",
                 "GL_ARB_fragment_coord_conventions"},
                0},
    FeatureGate{LanguageFeature::integer_operators, "the integer operators % << >> & | ^ ~", true, 130, 300,
                {"GL_EXT_gpu_shader4"}},
    // In no version: only with the extension (desktop and ES), as glslang.
    FeatureGate{LanguageFeature::control_flow_attributes, "attributes '[[ ]]'", true, 0, 0,
                {"GL_EXT_control_flow_attributes"}},
    FeatureGate{LanguageFeature::null_initializer, "empty initializers '{}'", true, 0, 0,
                {"GL_EXT_null_initializer"}},
};

// Keyed by layout identifier; `feature` is unused. Versions and extensions
// as in the GLSL 4.60 and ESSL 3.20 specifications and glslang.
constexpr std::array kLayoutGates = {
    std::pair{std::string_view("binding"),
              FeatureGate{{}, "", false, 420, 310,
                          {"GL_ARB_shading_language_420pack", "GL_ARB_shader_atomic_counters",
                           "GL_ARB_shader_image_load_store", "GL_ARB_shader_storage_buffer_object",
                           "GL_ARB_bindless_texture", "GL_ARB_uniform_buffer_object"}}},
    std::pair{std::string_view("offset"),
              FeatureGate{{}, "", false, 440, 310, {"GL_ARB_enhanced_layouts", "GL_ARB_shader_atomic_counters"}}},
    std::pair{std::string_view("align"), FeatureGate{{}, "", false, 440, 0, {"GL_ARB_enhanced_layouts"}}},
    std::pair{std::string_view("component"), FeatureGate{{}, "", false, 440, 0, {"GL_ARB_enhanced_layouts"}}},
    std::pair{std::string_view("xfb_buffer"), FeatureGate{{}, "", false, 440, 0, {"GL_ARB_enhanced_layouts"}}},
    std::pair{std::string_view("xfb_offset"), FeatureGate{{}, "", false, 440, 0, {"GL_ARB_enhanced_layouts"}}},
    std::pair{std::string_view("xfb_stride"), FeatureGate{{}, "", false, 440, 0, {"GL_ARB_enhanced_layouts"}}},
    std::pair{std::string_view("std430"),
              FeatureGate{{}, "", false, 430, 310, {"GL_ARB_shader_storage_buffer_object"}}},
    std::pair{std::string_view("invocations"),
              FeatureGate{{}, "", false, 400, 320,
                          {"GL_ARB_gpu_shader5", "GL_EXT_geometry_shader", "GL_OES_geometry_shader"}}},
    // `index` is not gated: subroutines, blend_func_extended and explicit_attrib_location all use it.
};

constexpr FeatureGate kLayoutExpressions{
    {}, "constant expressions in layout qualifiers", true, 440, 0, {"GL_ARB_enhanced_layouts"}};

bool allowed(const FeatureGate& g, const LanguageLevel& level) {
  int since = level.es ? g.es_since : g.desktop_since;
  if (since != 0 && level.version >= since) return true;
  for (std::string_view e : g.extensions) {
    if (!e.empty() && level.extension_enabled(e)) return true;
  }
  return false;
}

std::string requirement(const FeatureGate& g, std::string_view what, bool es) {
  std::string verb = g.plural ? " require " : " requires ";
  std::string extensions;
  for (std::size_t i = 0; i < g.named && !g.extensions[i].empty(); ++i) {
    extensions += (extensions.empty() ? "" : " or ") + std::string(g.extensions[i]);
  }
  if (g.desktop_since == 0 && g.es_since == 0 && !extensions.empty()) {  // an extension's, in no version
    return std::string(what) + verb + extensions;
  }
  if (es) {
    if (g.es_since == 0) {
      std::string base = std::string(what) + (g.plural ? " are" : " is") + " not available in GLSL ES";
      return extensions.empty() ? base : base + " (without " + extensions + ")";
    }
    return std::string(what) + verb + "#version " + std::to_string(g.es_since) + " es" +
           (extensions.empty() ? "" : " or " + extensions);
  }
  return std::string(what) + verb + "#version " + std::to_string(g.desktop_since) +
         (extensions.empty() ? "" : " or " + extensions);
}

const FeatureGate& gate(LanguageFeature feature) {
  for (const FeatureGate& g : kFeatureGates) {
    if (g.feature == feature) return g;
  }
  return kFeatureGates[0];  // unreachable: every feature has a gate
}

}  // namespace

std::span<const ExtensionInfo> known_extensions() { return kExtensions; }

bool glslang_knows_extension(std::string_view name) {
  static constexpr std::string_view kGlslangExtensions[] = {
#define GLSLANG_EXTENSION(name) #name,
#include "glslang_extensions.def"
#undef GLSLANG_EXTENSION
  };
  return std::binary_search(std::begin(kGlslangExtensions), std::end(kGlslangExtensions), name);
}

const ExtensionInfo* find_extension(std::string_view name) {
  auto it = std::lower_bound(kExtensions.begin(), kExtensions.end(), name,
                             [](const ExtensionInfo& e, std::string_view n) { return e.name < n; });
  if (it != kExtensions.end() && it->name == name) return &*it;
  if (name == kVulkanGlsl.name) return &kVulkanGlsl;
  return nullptr;
}

namespace {

// The extensions that make each family of type words keywords (glslang's Scan.cpp; this
// front end turns on the whole family with any of them, see ExtensionGroup::arithmetic_types).
struct TypeFamily {
  std::array<std::string_view, 4> prefixes;
  std::string_view extensions;
};
constexpr TypeFamily kTypeFamilies[] = {
    {{"int8_t", "uint8_t", "i8vec", "u8vec"}, "GL_EXT_shader_explicit_arithmetic_types_int8 (or GL_EXT_shader_8bit_storage)"},
    {{"int16_t", "uint16_t", "i16vec", "u16vec"},
     "GL_EXT_shader_explicit_arithmetic_types_int16 (or GL_EXT_shader_16bit_storage, GL_AMD_gpu_shader_int16)"},
    {{"int32_t", "uint32_t", "i32vec", "u32vec"}, "GL_EXT_shader_explicit_arithmetic_types_int32"},
    {{"int64_t", "uint64_t", "i64vec", "u64vec"}, "GL_EXT_shader_explicit_arithmetic_types_int64 (or GL_ARB_gpu_shader_int64)"},
    {{"float16_t", "f16vec", "f16mat", ""},
     "GL_EXT_shader_explicit_arithmetic_types_float16 (or GL_EXT_shader_16bit_storage, GL_AMD_gpu_shader_half_float)"},
    {{"float32_t", "f32vec", "f32mat", ""}, "GL_EXT_shader_explicit_arithmetic_types_float32"},
    {{"float64_t", "f64vec", "f64mat", ""}, "GL_EXT_shader_explicit_arithmetic_types_float64"},
    {{"i64image", "u64image", "", ""}, "GL_EXT_shader_image_int64"},
    {{"f16sampler", "f16image", "f16texture", "f16subpassInput"}, "GL_AMD_gpu_shader_half_float_fetch"},
};

}  // namespace

std::string_view extensions_declaring_type(std::string_view word) {
  const TokenKind kind = classify_word(word, KeywordContext::everything());
  if (!is_type_keyword(kind)) return {};
  for (const TypeFamily& f : kTypeFamilies)
    for (std::string_view prefix : f.prefixes)
      if (!prefix.empty() && word.substr(0, prefix.size()) == prefix) return f.extensions;
  return {};
}

std::vector<std::string> default_extension_macros() {
  std::vector<std::string> names;
  names.reserve(kExtensions.size());
  for (const ExtensionInfo& e : kExtensions) names.emplace_back(e.name);
  return names;
}

std::uint32_t extension_groups_enabled_by(std::string_view extension) {
  const ExtensionInfo* info = find_extension(extension);
  return info ? info->keyword_groups : 0;
}

bool LanguageLevel::extension_enabled(std::string_view name) const {
  return std::find(extensions.begin(), extensions.end(), name) != extensions.end();
}

bool LanguageLevel::allows(LanguageFeature feature) const { return allowed(gate(feature), *this); }

LanguageLevel LanguageLevel::everything() {
  LanguageLevel level;
  for (const FeatureGate& g : kFeatureGates) {
    for (std::string_view e : g.extensions) {
      if (!e.empty()) level.extensions.emplace_back(e);
    }
  }
  return level;
}

std::string feature_requirement(LanguageFeature feature, bool es) {
  const FeatureGate& g = gate(feature);
  return requirement(g, g.what, es);
}

std::string layout_id_requirement(std::string_view id, const LanguageLevel& level) {
  for (const auto& [name, g] : kLayoutGates) {
    if (name == id) return allowed(g, level) ? "" : requirement(g, "layout(" + std::string(id) + ")", level.es);
  }
  return "";
}

std::string layout_expression_requirement(const LanguageLevel& level) {
  return allowed(kLayoutExpressions, level) ? "" : requirement(kLayoutExpressions, kLayoutExpressions.what, level.es);
}

}  // namespace safegi
