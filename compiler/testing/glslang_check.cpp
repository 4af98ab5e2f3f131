#include "glslang_check.hpp"

#include <mutex>
#include <vector>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <safegi/diagnostics/file.hpp>

#include "../src/glslang_language.hpp"

namespace safegi::testing {
namespace {

void initialise() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

}  // namespace

GlslangVerdict glslang_validate(const std::string& glsl, Stage stage) {
  initialise();
  glslang::TShader shader(glslang_language(stage));
  const char* text = glsl.c_str();
  shader.setStrings(&text, 1);
  GlslangVerdict verdict;
  verdict.accepted = shader.parse(GetDefaultResources(), 100, false, EShMsgDefault);
  if (!verdict.accepted) verdict.log = shader.getInfoLog();
  return verdict;
}

std::optional<int> spirv_instruction_count(const std::string& glsl, Stage stage, std::string* log) {
  initialise();
  const EShLanguage language = glslang_language(stage);
  glslang::TShader shader(language);
  const char* text = glsl.c_str();
  shader.setStrings(&text, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientOpenGL, 100);
  shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
  // Plain OpenGL GLSL has no explicit uniform locations; let glslang assign them.
  shader.setAutoMapLocations(true);
  shader.setAutoMapBindings(true);
  const auto messages = static_cast<EShMessages>(EShMsgSpvRules);
  if (!shader.parse(GetDefaultResources(), 100, false, messages)) {
    if (log) *log = shader.getInfoLog();
    return std::nullopt;
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) {
    if (log) *log = program.getInfoLog();
    return std::nullopt;
  }
  std::vector<unsigned int> words;
  glslang::GlslangToSpv(*program.getIntermediate(language), words);
  int count = 0;
  for (std::size_t i = 5; i < words.size();) {
    const unsigned length = words[i] >> 16;
    ++count;
    i += length == 0 ? 1 : length;
  }
  return count;
}

std::string read_text_file(const std::filesystem::path& path) { return read_file(path.string()).value_or(""); }

}  // namespace safegi::testing
