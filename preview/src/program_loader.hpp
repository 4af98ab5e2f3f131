// The seam between the preview and the shader compiler: annotated sources in,
// a runtime_gl Program (GLSL + symbol table per stage) out. Loading compiles
// in process through safegi::compile; annotation errors come back as the
// compiler's diagnostics (file:line:col), driver errors as runtime_gl maps them.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <safegi/runtime_gl/program.hpp>

namespace safegi::preview {

class ShaderLoadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The text of one of preview/shaders/*, compiled into the library.
std::optional<std::string_view> embedded_shader(std::string_view name);

// How the compiled shaders reach the driver: as the plain GLSL, or as SPIR-V
// made from it by glslang (OpenGL target) through GL_ARB_gl_spirv.
enum class ShaderFormat { glsl, spirv };

struct ShaderFile {
  std::string path;  // names the file in diagnostics; the stage comes from its extension
  std::string text;
};

// Compiles `files` as one program (with the given -D defines) and links it.
gl::Program load_program(const std::vector<ShaderFile>& files, const std::vector<std::pair<std::string, std::string>>& defines,
                         std::string name, ShaderFormat format = ShaderFormat::glsl);

// The same for shaders embedded from preview/shaders/, by file name.
gl::Program load_embedded_program(const std::vector<std::string>& names,
                                  const std::vector<std::pair<std::string, std::string>>& defines, std::string name,
                                  ShaderFormat format = ShaderFormat::glsl);

}  // namespace safegi::preview
