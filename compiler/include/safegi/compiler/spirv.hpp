#pragma once
// SPIR-V from the compiler's plain GLSL, through the glslang library: what
// `safeglslc -V` / `-G` write and what runtime_gl loads through
// GL_ARB_gl_spirv. The annotations are gone before glslang sees the text, so
// the module is the one glslangValidator makes of the emitted GLSL with the
// same options (tested byte for byte); the symbol table is the compiler's,
// unchanged.
//
//   safegi::CompileResult r = safegi::compile(sources);
//   safegi::SpirvResult spirv = safegi::to_spirv(r, {.client = safegi::SpirvClient::opengl});
//   if (!spirv.success) std::cerr << spirv.log;

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <safegi/compiler/compile.hpp>

namespace safegi {

enum class SpirvClient { vulkan, opengl };

struct SpirvOptions {
  SpirvClient client = SpirvClient::vulkan;  // -V (Vulkan semantics) or -G (OpenGL semantics)
  int client_version = 100;                  // -V100 / -G100: the value of the VULKAN / GL_SPIRV macro
  int vulkan_minor = 0;                      // --target-env vulkan1.<n>, n = 0..3 (Vulkan only)
  // --target-env spirv1.<n>; default: the environment's (vulkan1.0: 1.0,
  // vulkan1.1: 1.3, vulkan1.2: 1.5, vulkan1.3: 1.6, opengl: 1.0), as glslangValidator.
  std::optional<int> spirv_minor;
  // Locations for in/out and default-block uniforms, bindings for samplers and
  // blocks, where the source gives none (--aml, --amb). Default: on for OpenGL,
  // whose GLSL rarely has them and whose SPIR-V needs them, off for Vulkan.
  // All stages are linked as one program first, so an output and the next
  // stage's input of the same name get the same location, and a uniform
  // declared in two stages gets one location.
  std::optional<bool> auto_map_locations;
  std::optional<bool> auto_map_bindings;
  bool relaxed_vulkan_rules = false;  // -R: default-block uniforms allowed (glslang gathers them into a block)
  bool debug_info = false;            // -g: OpLine and the source in the module
};

struct SpirvModule {
  Stage stage = Stage::unknown;
  std::string path;                  // the annotated source it came from
  std::vector<std::uint32_t> words;  // the module, header included
};

struct SpirvResult {
  bool success = false;
  std::vector<SpirvModule> modules;  // one per stage, in the order of the compile's sources
  std::string log;  // glslang's messages as "file:line: error: ..." of the annotated sources
};

// Every stage of `compiled` (a successful compile) through glslang as one
// program. Thread-safe. Target SafeGI::spirv (links glslang); the two
// functions below are in SafeGI::compiler.
SpirvResult to_spirv(const CompileResult& compiled, const SpirvOptions& options = {});

// A module as the bytes of a .spv file (little-endian words).
std::string spirv_bytes(const std::vector<std::uint32_t>& words);

// glslangValidator's --target-env values: vulkan1.0 … vulkan1.3, opengl,
// spirv1.0 … spirv1.6 (the last only sets the SPIR-V version). False when
// `name` is none of them.
bool apply_target_env(std::string_view name, SpirvOptions& options);

}  // namespace safegi
