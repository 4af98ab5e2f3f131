#include "program_loader.hpp"

#include <safegi/compiler/compile.hpp>
#include <safegi/compiler/spirv.hpp>

namespace safegi::preview {

gl::Program load_program(const std::vector<ShaderFile>& files,
                         const std::vector<std::pair<std::string, std::string>>& defines, std::string name,
                         ShaderFormat format) {
  std::vector<ShaderSource> sources;
  for (const ShaderFile& file : files) sources.push_back({file.path, file.text, std::nullopt});
  CompileOptions options;
  options.defines = defines;
  CompileResult result = compile(sources, options);
  if (!result.success) throw ShaderLoadError(result.diagnostics_text(false));
  std::vector<gl::ProgramSource> stages;
  for (const StageOutput& stage : result.stages) {
    std::optional<gl::Stage> table_stage = to_table_stage(stage.stage);
    if (!table_stage) throw ShaderLoadError(stage.path + ": error: a stage runtime_gl cannot load");
    stages.push_back({*table_stage, stage.glsl, result.symbols});
  }
  if (format == ShaderFormat::spirv) {
    // Every stage in one glslang program: locations agree across stages.
    SpirvResult spirv = to_spirv(result, SpirvOptions{.client = SpirvClient::opengl});
    if (!spirv.success) throw ShaderLoadError(spirv.log);
    for (std::size_t i = 0; i < stages.size(); ++i) stages[i].spirv = std::move(spirv.modules[i].words);
  }
  return gl::Program(std::move(stages), std::move(name));
}

gl::Program load_embedded_program(const std::vector<std::string>& names,
                                  const std::vector<std::pair<std::string, std::string>>& defines, std::string name,
                                  ShaderFormat format) {
  std::vector<ShaderFile> files;
  for (const std::string& file : names) {
    std::optional<std::string_view> text = embedded_shader(file);
    if (!text) throw ShaderLoadError("safegi-preview: error: no embedded shader named '" + file + "'");
    files.push_back({"preview/shaders/" + file, std::string(*text)});
  }
  return load_program(files, defines, std::move(name), format);
}

}  // namespace safegi::preview
