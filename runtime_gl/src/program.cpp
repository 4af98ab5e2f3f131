#include "safegi/runtime_gl/program.hpp"

#include <glad/gl.h>

#include <algorithm>

#include "safegi/symbol_table/driver_log.hpp"
#include "safegi/symbol_table/error.hpp"

namespace safegi::gl {
namespace {

GLenum shader_kind(Stage stage) {
  switch (stage) {
    case Stage::vertex: return GL_VERTEX_SHADER;
    case Stage::tess_control: return GL_TESS_CONTROL_SHADER;
    case Stage::tess_evaluation: return GL_TESS_EVALUATION_SHADER;
    case Stage::geometry: return GL_GEOMETRY_SHADER;
    case Stage::fragment: return GL_FRAGMENT_SHADER;
    case Stage::compute: return GL_COMPUTE_SHADER;
    default: break;  // mesh shading and ray tracing: Vulkan only
  }
  return 0;
}

template <class GetInteger, class GetLog>
std::string info_log(GLuint object, GetInteger get_integer, GetLog get_log) {
  GLint length = 0;
  get_integer(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(length > 0 ? length : 0), '\0');
  if (length > 0) get_log(object, length, nullptr, log.data());
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log;
}

std::string_view interface_words(Interface interface) {
  switch (interface) {
    case Interface::uniform: return "uniform";
    case Interface::uniform_array: return "uniform array";
    case Interface::attribute: return "vertex attribute";
    case Interface::output: return "fragment output";
    case Interface::sampler: return "sampler";
  }
  return "?";
}

Storage storage_of(Interface interface) {
  switch (interface) {
    case Interface::attribute: return Storage::input;
    case Interface::output: return Storage::output;
    default: return Storage::uniform;
  }
}

// Vertex inputs live in the vertex stage and outputs in the fragment stage;
// uniforms may be declared in any stage.
bool stage_holds(Interface interface, Stage stage) {
  if (interface == Interface::attribute) return stage == Stage::vertex;
  if (interface == Interface::output) return stage == Stage::fragment;
  return true;
}

// A stage entry of the table that came with a source; a program-mode table
// lists several, a shader-mode one exactly one.
StageSymbols stage_entry(const ProgramSource& source, const std::string& program_name) {
  if (const StageSymbols* entry = source.symbols.stage(source.stage)) return *entry;
  throw ShaderError(program_name + ": error: the symbol table given for the " +
                    std::string(to_string(source.stage)) + " stage has no entry for it");
}

// Compiles one stage from its GLSL or, when it has one, its SPIR-V module
// (entry point main, no specialization constants); false with `log` set on failure.
bool compile_stage(GLuint shader, const ProgramSource& source, std::string& log) {
  if (source.spirv.empty()) {
    const char* text = source.glsl.c_str();
    const auto length = static_cast<GLint>(source.glsl.size());
    glShaderSource(shader, 1, &text, &length);
    glCompileShader(shader);
  } else {
    glShaderBinary(1, &shader, GL_SHADER_BINARY_FORMAT_SPIR_V_ARB, source.spirv.data(),
                   static_cast<GLsizei>(source.spirv.size() * sizeof(std::uint32_t)));
    glSpecializeShaderARB(shader, "main", 0, nullptr, nullptr);
  }
  GLint compiled = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
  if (!compiled) log = info_log(shader, glGetShaderiv, glGetShaderInfoLog);
  return compiled == GL_TRUE;
}

// Each stage's interface, merged: uniforms from every stage, inputs from the
// vertex stage, outputs from the fragment stage (what stage_holds allows).
SpirvInterface program_interface(const std::vector<ProgramSource>& sources, const std::string& name) {
  SpirvInterface merged;
  for (const ProgramSource& source : sources) {
    SpirvInterface stage = read_spirv_interface(source.spirv, name + " (" + std::string(to_string(source.stage)) + ")");
    merged.uniforms.merge(stage.uniforms);
    if (source.stage == Stage::vertex) merged.inputs = std::move(stage.inputs);
    if (source.stage == Stage::fragment) merged.outputs = std::move(stage.outputs);
  }
  return merged;
}

}  // namespace

bool spirv_programs_supported() { return GLAD_GL_ARB_gl_spirv != 0; }

Program::Program(std::vector<ProgramSource> sources, std::string name)
    : object_(detail::ObjectKind::program, glCreateProgram()), name_(std::move(name)) {
  std::string errors;
  std::vector<GLuint> shaders;
  for (const auto& source : sources) {
    if (shader_kind(source.stage) == 0)
      throw ShaderError(name_ + ": error: a " + std::string(to_string(source.stage)) +
                        " shader is Vulkan's (OpenGL has no such stage); bind it through a Vulkan pipeline");
    stages_.push_back(stage_entry(source, name_));
    if (stages_.back().client == Client::vulkan)
      throw ShaderError(name_ + ": error: the " + std::string(to_string(source.stage)) +
                        " stage was compiled for Vulkan (-V or --target-env vulkan*: descriptor sets, push constants); "
                        "for OpenGL compile it without -V, or to SPIR-V with -G");
    for (const auto& derived : source.symbols.derived_dimensions) namer_.add(derived.name, derived.exponents);
  }
  const auto spirv_stages = std::count_if(sources.begin(), sources.end(), [](const auto& s) { return !s.spirv.empty(); });
  if (spirv_stages != 0) {
    if (static_cast<std::size_t>(spirv_stages) != sources.size())
      throw ShaderError(name_ + ": error: a program is either all SPIR-V or all GLSL (GL links no mix of the two)");
    if (!spirv_programs_supported()) {
      const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
      throw ShaderError(name_ + ": error: the driver (" + (renderer ? renderer : "unknown renderer") +
                        ") does not offer GL_ARB_gl_spirv, so SPIR-V cannot be loaded; load the GLSL instead");
    }
    spirv_ = program_interface(sources, name_);
  }
  for (std::size_t i = 0; i < sources.size(); ++i) {
    const ProgramSource& source = sources[i];
    GLuint shader = glCreateShader(shader_kind(source.stage));
    std::string log;
    if (!compile_stage(shader, source, log)) errors += map_driver_log(log, stages_[i]);
    glAttachShader(id(), shader);
    shaders.push_back(shader);
  }
  if (errors.empty()) {
    glLinkProgram(id());
    GLint linked = GL_FALSE;
    glGetProgramiv(id(), GL_LINK_STATUS, &linked);
    if (!linked)
      errors = name_ + ": error: the driver could not link the program:\n" +
               info_log(id(), glGetProgramiv, glGetProgramInfoLog) + '\n';
  }
  for (GLuint shader : shaders) {
    glDetachShader(id(), shader);
    glDeleteShader(shader);
  }
  if (!errors.empty()) {
    errors.pop_back();
    throw ShaderError(errors);
  }
}

void Program::use() const { glUseProgram(id()); }

const Symbol* Program::find(Interface interface, std::string_view name, const StageSymbols** stage) const {
  for (const auto& entry : stages_) {
    if (!stage_holds(interface, entry.stage)) continue;
    if (const Symbol* symbol = entry.find(storage_of(interface), name)) {
      if (stage) *stage = &entry;
      return symbol;
    }
  }
  return nullptr;
}

void Program::check(Interface interface, std::string_view name, const ValueType& host) const {
  const std::string what(interface_words(interface));
  const Symbol* symbol = find(interface, name, nullptr);
  if (!symbol) {
    std::string files;
    for (const auto& entry : stages_) {
      if (!stage_holds(interface, entry.stage)) continue;
      files += (files.empty() ? "" : ", ") + entry.file;
    }
    throw BindingError(name_ + ": error: no " + what + " named '" + std::string(name) + "' in " +
                       (files.empty() ? "the program" : files));
  }
  const std::string where = to_string(symbol->declared_at) + ": error: " + what + " '" + std::string(name) + "'";
  if (!symbol->block.empty())
    throw BindingError(where + " is a member of uniform block '" + symbol->block +
                       "'; set it through a uniform buffer");
  const bool is_array = symbol->array_size.has_value();
  if (is_array != (interface == Interface::uniform_array)) {
    throw BindingError(where + (is_array ? " is an array of " + std::to_string(*symbol->array_size) +
                                               "; look it up with uniform_array<T>"
                                         : " is not an array; look it up with uniform<T>"));
  }
  const bool is_sampler = symbol->type.kind == Kind::sampler;
  if (interface == Interface::sampler && !is_sampler)
    throw BindingError(where + " is declared as " + in_words(symbol->type, namer_) + ", not as a sampler");
  if (interface == Interface::sampler && symbol->type.glsl_type != "sampler2D")
    throw BindingError(where + " is a " + symbol->type.glsl_type + "; only sampler2D takes a texture2d");
  const ValueType& declared = interface == Interface::sampler ? *symbol->texel : symbol->type;
  std::vector<std::string> parts = differences(declared, host);
  if (parts.empty()) return;
  std::string differ;
  for (std::size_t i = 0; i < parts.size(); ++i)
    differ += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
  const std::string texel = interface == Interface::sampler ? " texels" : "";
  throw BindingError(where + " is declared with" + texel + " type " + in_words(declared, namer_) +
                     " but the host uses " + in_words(host, namer_) + " (" + differ + " differ" +
                     (parts.size() == 1 ? "s" : "") + ')');
}

int Program::locate(Interface interface, std::string_view name, const ValueType* host) const {
  if (host) check(interface, name, *host);
  if (spirv_) {
    const auto& by_name = interface == Interface::attribute ? spirv_->inputs
                        : interface == Interface::output    ? spirv_->outputs
                                                            : spirv_->uniforms;
    const auto found = by_name.find(name);
    return found == by_name.end() ? -1 : found->second;
  }
  const std::string name_z(name);
  switch (interface) {
    case Interface::attribute: return glGetAttribLocation(id(), name_z.c_str());
    case Interface::output: return glGetFragDataLocation(id(), name_z.c_str());
    default: return glGetUniformLocation(id(), name_z.c_str());
  }
}

void Program::expect_source_hash(Stage stage, std::string_view hash) const {
  for (const auto& entry : stages_) {
    if (entry.stage != stage) continue;
    if (entry.source_hash == hash) return;
    throw BindingError(name_ + ": error: the handles were generated from " + entry.file + " with source hash " +
                       std::string(hash) + ", but the program was built from source hash " +
                       (entry.source_hash.empty() ? "(none)" : entry.source_hash) + "; regenerate the header");
  }
  throw BindingError(name_ + ": error: the handles expect a " + std::string(to_string(stage)) +
                     " stage, which the program does not have");
}

int Program::array_size(std::string_view name) const {
  const Symbol* symbol = find(Interface::uniform_array, name, nullptr);
  return symbol && symbol->array_size ? *symbol->array_size : 0;
}

}  // namespace safegi::gl
