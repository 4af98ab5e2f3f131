#include "safegi/compiler/spirv.hpp"

#include <algorithm>
#include <memory>
#include <mutex>
#include <regex>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/MachineIndependent/iomapper.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <safegi/diagnostics/codes.hpp>
#include <safegi/symbol_table/driver_log.hpp>

#include "glslang_language.hpp"

namespace safegi {
namespace {

constexpr glslang::EShTargetClientVersion kVulkanVersions[] = {
    glslang::EShTargetVulkan_1_0, glslang::EShTargetVulkan_1_1, glslang::EShTargetVulkan_1_2,
    glslang::EShTargetVulkan_1_3};
constexpr glslang::EShTargetLanguageVersion kSpirvVersions[] = {
    glslang::EShTargetSpv_1_0, glslang::EShTargetSpv_1_1, glslang::EShTargetSpv_1_2, glslang::EShTargetSpv_1_3,
    glslang::EShTargetSpv_1_4, glslang::EShTargetSpv_1_5, glslang::EShTargetSpv_1_6};

// glslangValidator's defaults: each Vulkan version's own SPIR-V, 1.0 for OpenGL.
int default_spirv_minor(const SpirvOptions& options) {
  if (options.client == SpirvClient::opengl) return 0;
  constexpr int kByVulkan[] = {0, 3, 5, 6};
  return kByVulkan[options.vulkan_minor];
}

void initialise_glslang() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

// The symbol-table entry of a stage, for mapping glslang's "0:12" to "file:12".
const gl::StageSymbols* table_entry(const CompileResult& compiled, Stage stage) {
  const std::optional<gl::Stage> table_stage = to_table_stage(stage);
  return table_stage ? compiled.symbols.stage(*table_stage) : nullptr;
}

// " [E-SPIRV]": how a diagnostic line ends with its code.
std::string code_suffix(std::string_view code) {
  std::string suffix = " [";
  suffix += code;
  suffix += ']';
  return suffix;
}

// "safeglslc: error: <what> [E-SPIRV]", a line of the log.
std::string driver_error_line(std::string_view what) {
  std::string line = "safeglslc: error: ";
  line += what;
  line += code_suffix(code::E_SPIRV);
  line += '\n';
  return line;
}

std::string mapped_log(std::string log, const CompileResult& compiled, Stage stage, const std::string& path) {
  // glslang's summary ("ERROR: 2 compilation errors.  No code generated."):
  // safeglslc counts the errors itself.
  for (std::size_t at = log.find(" compilation errors."); at != std::string::npos; at = log.find(" compilation errors.")) {
    const std::size_t begin = log.rfind('\n', at) == std::string::npos ? 0 : log.rfind('\n', at) + 1;
    const std::size_t end = log.find('\n', at);
    log.erase(begin, end == std::string::npos ? std::string::npos : end - begin + 1);
  }
  if (log.find_first_not_of(" \n") == std::string::npos) return {};
  const gl::StageSymbols* entry = table_entry(compiled, stage);
  std::string mapped = entry ? gl::map_driver_log(log, *entry) : path + ": " + log;
  // Lines without a location ("ERROR: #version: ...") are kept after the file
  // name; they are errors and warnings like the others.
  for (const auto& [from, to] : {std::pair{": ERROR: ", ": error: "}, std::pair{": WARNING: ", ": warning: "}})
    for (std::size_t at = mapped.find(from); at != std::string::npos; at = mapped.find(from, at))
      mapped.replace(at, std::string_view(from).size(), to);
  // glslang's messages are the SPIR-V step's diagnostics: each ends with its code, as the checker's do.
  std::string coded;
  for (std::size_t begin = 0; begin < mapped.size();) {
    const std::size_t end = std::min(mapped.find('\n', begin), mapped.size());
    const std::string_view line = std::string_view(mapped).substr(begin, end - begin);
    coded += line;
    if (line.find(": error: ") != std::string_view::npos) coded += code_suffix(code::E_SPIRV);
    else if (line.find(": warning: ") != std::string_view::npos) coded += code_suffix(code::W_SPIRV);
    coded += '\n';
    begin = end + 1;
  }
  return coded;
}

// A GLSL type that takes one uniform location (an array one per element);
// struct types, whose sizes the symbol table does not give, are not.
bool is_builtin_glsl_type(const std::string& type) {
  static const std::regex kBuiltin(
      R"((float|double|u?int|bool|atomic_uint|[ibud]?vec[234]|d?mat[234](x[234])?|[iu]?(sampler|image)[0-9A-Z]\w*))");
  return std::regex_match(type, kBuiltin);
}

// Locations for the default-block uniforms of the whole program. glslang's
// auto-mapping numbers each stage's uniforms from 0 on its own (so a vertex
// and a fragment uniform of different names would share location 0, and
// glslangValidator -l does just that); GL wants one location space per
// program. So: every stage's uniforms in pipeline order, each name once, in
// declaration order, an array taking one location per element, explicit
// layout(location) kept and stepped around. For a single stage this is the
// order glslang's own auto-mapping takes. Struct-typed uniforms (whose size
// the table does not give) are left to glslang, numbered after these.
struct UniformLocations {
  std::vector<std::pair<std::string, int>> assigned;
  int next_free = 0;
  bool explicit_locations = false;  // some uniform has layout(location)
};

UniformLocations program_uniform_locations(const CompileResult& compiled) {
  std::vector<const gl::StageSymbols*> stages;
  for (const gl::StageSymbols& stage : compiled.symbols.stages) stages.push_back(&stage);
  // glslang numbers them in its order of stages (EShLanguage), not the pipeline's.
  auto glslang_order = [](gl::Stage stage) {
    switch (stage) {
#define SAFEGI_STAGE(id, ...) \
  case gl::Stage::id: return static_cast<int>(glslang_language(Stage::id));
#include <safegi/symbol_table/stages.def>
    }
    return 0;
  };
  std::stable_sort(stages.begin(), stages.end(),
                   [&](const auto* a, const auto* b) { return glslang_order(a->stage) < glslang_order(b->stage); });
  // In glslang's order (TVarEntryInfo::TOrderByPriority): a layout(binding) first, then
  // layout(set), then declaration order.
  auto uniforms = [](const gl::StageSymbols& stage) {
    std::vector<const gl::Symbol*> out;
    for (const gl::Symbol& symbol : stage.symbols)
      if (symbol.storage == gl::Storage::uniform && symbol.block.empty() && symbol.type.kind != gl::Kind::block)
        out.push_back(&symbol);
    std::stable_sort(out.begin(), out.end(), [](const gl::Symbol* a, const gl::Symbol* b) { return a->binding && !b->binding; });
    return out;
  };
  std::vector<bool> taken;
  auto take = [&](int first, int count) {
    if (static_cast<int>(taken.size()) < first + count) taken.resize(static_cast<std::size_t>(first + count), false);
    for (int i = first; i < first + count; ++i) taken[static_cast<std::size_t>(i)] = true;
  };
  auto size_of = [](const gl::Symbol& symbol) { return std::max(1, symbol.array_size.value_or(1)); };
  UniformLocations result;
  for (const auto* stage : stages)
    for (const gl::Symbol* symbol : uniforms(*stage))
      if (symbol->location) {
        take(*symbol->location, size_of(*symbol));
        result.explicit_locations = true;
      }
  std::vector<std::string> named;
  for (const auto* stage : stages) {
    for (const gl::Symbol* symbol : uniforms(*stage)) {
      if (symbol->location || !is_builtin_glsl_type(symbol->type.glsl_type)) continue;
      if (std::find(named.begin(), named.end(), symbol->name) != named.end()) continue;
      named.push_back(symbol->name);
      const int size = size_of(*symbol);
      int first = 0;
      for (;; ++first) {
        bool free = true;
        for (int i = first; i < first + size && free; ++i)
          free = i >= static_cast<int>(taken.size()) || !taken[static_cast<std::size_t>(i)];
        if (free) break;
      }
      take(first, size);
      result.assigned.emplace_back(symbol->name, first);
    }
  }
  result.next_free = static_cast<int>(taken.size());
  return result;
}

SpirvResult to_spirv_one_by_one(const CompileResult& compiled, const SpirvOptions& options) {
  SpirvResult result;
  result.success = true;
  for (const StageOutput& stage : compiled.stages) {
    CompileResult single = compiled;
    single.stages = {stage};
    SpirvResult one = to_spirv(single, options);
    result.log += one.log;
    result.success = result.success && one.success;
    for (SpirvModule& module : one.modules) result.modules.push_back(std::move(module));
  }
  return result;
}

}  // namespace

SpirvResult to_spirv(const CompileResult& compiled, const SpirvOptions& options) {
  SpirvResult result;
  if (!compiled.success) {
    result.log = driver_error_line("SPIR-V needs a shader that compiled without errors");
    return result;
  }
  if (options.vulkan_minor < 0 || options.vulkan_minor > 3 || options.spirv_minor.value_or(0) < 0 ||
      options.spirv_minor.value_or(0) > 6) {
    result.log = driver_error_line("SPIR-V targets are vulkan1.0 … vulkan1.3 and spirv1.0 … spirv1.6");
    return result;
  }
  // glslang links one entry point per stage: a ray-tracing pipeline's several
  // hit or miss shaders become one module each, compiled on their own (their
  // payloads were checked against each other before).
  for (std::size_t i = 0; i < compiled.stages.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (compiled.stages[i].stage == compiled.stages[j].stage) return to_spirv_one_by_one(compiled, options);
  initialise_glslang();
  const bool vulkan = options.client == SpirvClient::vulkan;
  const int spirv_minor = options.spirv_minor.value_or(default_spirv_minor(options));
  int message_bits = EShMsgSpvRules;
  if (vulkan) message_bits |= EShMsgVulkanRules;
  if (options.debug_info) message_bits |= EShMsgDebugInfo;
  const auto messages = static_cast<EShMessages>(message_bits);
  const glslang::EShClient client = vulkan ? glslang::EShClientVulkan : glslang::EShClientOpenGL;

  const bool map_locations = options.auto_map_locations.value_or(!vulkan);
  const UniformLocations uniform_locations = program_uniform_locations(compiled);

  // The shaders outlive the program that links them (glslang's rule).
  std::vector<std::unique_ptr<glslang::TShader>> shaders;
  glslang::TProgram program;
  for (const StageOutput& stage : compiled.stages) {
    const EShLanguage language = glslang_language(stage.stage);
    auto shader = std::make_unique<glslang::TShader>(language);
    // No string names: glslang then says "0:12", which map_driver_log turns
    // into the annotated file (or the #include'd one) and line.
    const char* text = stage.glsl.c_str();
    shader->setStrings(&text, 1);
    shader->setEnvInput(glslang::EShSourceGlsl, language, client, options.client_version);
    shader->setEnvClient(client, vulkan ? kVulkanVersions[options.vulkan_minor] : glslang::EShTargetOpenGL_450);
    shader->setEnvTarget(glslang::EShTargetSpv, kSpirvVersions[spirv_minor]);
    if (options.relaxed_vulkan_rules && vulkan) shader->setEnvInputVulkanRulesRelaxed();
    shader->setAutoMapLocations(map_locations);
    // One stage: glslang's own numbering, as glslangValidator -G gives it. Several, or an
    // explicit layout(location) that glslang's numbering would alias: one location space for
    // the program, stepping around the explicit ones (docs/safeglslc.md).
    if (map_locations && !vulkan && (compiled.stages.size() > 1 || uniform_locations.explicit_locations)) {
      for (const auto& [name, location] : uniform_locations.assigned) shader->addUniformLocationOverride(name.c_str(), location);
      shader->setUniformLocationBase(uniform_locations.next_free);
    }
    shader->setAutoMapBindings(options.auto_map_bindings.value_or(!vulkan));
    if (options.debug_info) shader->setDebugInfo(true);
    // The emitted GLSL always has its #version; 100 is glslangValidator's default otherwise.
    if (!shader->parse(GetDefaultResources(), 100, false, messages)) {
      result.log += mapped_log(shader->getInfoLog(), compiled, stage.stage, stage.path);
      continue;
    }
    program.addShader(shader.get());
    shaders.push_back(std::move(shader));
  }
  if (!result.log.empty()) return result;
  // Several stages: glslang's GLSL mapper, which matches an output and the
  // next stage's input by name (its default mapper numbers each stage on its
  // own, as glslangValidator does).
  bool mapped = program.link(messages);
  if (mapped && shaders.size() > 1) {
    glslang::TGlslIoMapper cross_stage_mapper;
    glslang::TDefaultGlslIoResolver resolver(*shaders.front()->getIntermediate());
    mapped = program.mapIO(&resolver, &cross_stage_mapper);
  } else if (mapped) {
    mapped = program.mapIO();
  }
  if (!mapped) {
    result.log = std::string(program.getInfoLog()) + program.getInfoDebugLog();
    if (!compiled.stages.empty())
      result.log = mapped_log(result.log, compiled, compiled.stages.front().stage, compiled.stages.front().path);
    return result;
  }
  for (const StageOutput& stage : compiled.stages) {
    SpirvModule module;
    module.stage = stage.stage;
    module.path = stage.path;
    glslang::SpvOptions spv_options;
    spv_options.generateDebugInfo = options.debug_info;
    spv::SpvBuildLogger logger;
    std::vector<unsigned int> words;
    glslang::GlslangToSpv(*program.getIntermediate(glslang_language(stage.stage)), words, &logger, &spv_options);
    module.words.assign(words.begin(), words.end());
    const std::string messages_text = logger.getAllMessages();
    if (!messages_text.empty()) result.log += stage.path + ": " + messages_text;
    result.modules.push_back(std::move(module));
  }
  result.success = true;
  return result;
}

}  // namespace safegi
