#pragma once
// A linked GL program built from the elider's GLSL and the compiler's symbol
// table, with typed lookups: `auto le = program.uniform<spectrum<radiance>>("Le");
// program.set(le, value);`. In the checked build a lookup compares the C++ type
// with the shader's declaration (name, GLSL type, kind, dimension, space) and
// throws BindingError naming the declaration and both types in words; in the
// unchecked build (SAFEGI_GL_UNCHECKED) it only asks the driver. Both builds
// issue the same GL calls.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "safegi/runtime_gl/handles.hpp"
#include "safegi/runtime_gl/resources.hpp"
#include "safegi/symbol_table/spirv_interface.hpp"
#include "safegi/symbol_table/symbol_table.hpp"
#include "safegi/symbol_table/value_traits.hpp"

namespace safegi::gl {

// One stage as the compiler hands it over: plain GLSL plus the symbol table
// that describes it (a shader-mode table, or a program-mode table that has an
// entry for this stage). safegi::compile() will produce these in-process.
// With `spirv` (safegi::to_spirv of that GLSL, OpenGL target) the stage is
// loaded as SPIR-V through GL_ARB_gl_spirv; the table is the same.
struct ProgramSource {
  Stage stage;
  std::string glsl;
  SymbolTable symbols;
  std::vector<std::uint32_t> spirv = {};
};

// Whether the current context loads SPIR-V stages (GL_ARB_gl_spirv or GL 4.6).
bool spirv_programs_supported();

// What a lookup is for; decides where the symbol lives and how GL finds it.
enum class Interface { uniform, uniform_array, attribute, output, sampler };

class Program {
 public:
  // Compiles and links; throws ShaderError with the driver's messages mapped
  // to the annotated sources (file:line:col). `name` labels messages.
  explicit Program(std::vector<ProgramSource> sources, std::string name = "program");

  unsigned id() const { return object_.name(); }
  const std::string& name() const { return name_; }
  const std::vector<StageSymbols>& stages() const { return stages_; }
  void use() const;

  template <gl_value T, class Mode = build_mode>
  uniform_id<T> uniform(std::string_view name) const {
    return {locate(Interface::uniform, name, host_type<T, Mode>().get())};
  }
  template <gl_value T, class Mode = build_mode>
  uniform_array_id<T> uniform_array(std::string_view name) const {
    return {locate(Interface::uniform_array, name, host_type<T, Mode>().get()), array_size(name)};
  }
  template <gl_value T, class Mode = build_mode>
  attribute_id<T> attribute(std::string_view name) const {
    return {locate(Interface::attribute, name, host_type<T, Mode>().get())};
  }
  template <gl_value T, class Mode = build_mode>
  output_id<T> output(std::string_view name) const {
    return {locate(Interface::output, name, host_type<T, Mode>().get())};
  }
  // T is the texel type of the texture2d<T> that will be bound to it.
  template <gl_value T, class Mode = build_mode>
  sampler_id<T> sampler(std::string_view name) const {
    return {locate(Interface::sampler, name, host_type<T, Mode>().get())};
  }

  template <gl_value T>
  void set(uniform_id<T> uniform, const T& value) const {
    const gl_type_of<T> data = value_traits<T>::to_gl(value);
    detail::set_uniform(id(), uniform.location, gl_layout_of<T>::scalar, gl_layout_of<T>::components,
                        gl_layout_of<T>::columns, 1, &data);
  }
  // Any contiguous range of exactly T converts (std::array, std::vector, span).
  template <gl_value T>
  void set(uniform_array_id<T> uniform, std::type_identity_t<std::span<const T>> values) const {
    if (static_cast<int>(values.size()) > uniform.size)
      throw BindingError(name_ + ": error: " + std::to_string(values.size()) + " values for a uniform array of " +
                         std::to_string(uniform.size));
    const auto count = static_cast<int>(values.size());
    if constexpr (gl_storable<T>) {
      detail::set_uniform(id(), uniform.location, gl_layout_of<T>::scalar, gl_layout_of<T>::components,
                          gl_layout_of<T>::columns, count, values.data());
    } else {
      std::vector<gl_type_of<T>> data;
      data.reserve(values.size());
      for (const T& value : values) data.push_back(value_traits<T>::to_gl(value));
      detail::set_uniform(id(), uniform.location, gl_layout_of<T>::scalar, gl_layout_of<T>::components,
                          gl_layout_of<T>::columns, count, data.data());
    }
  }
  // Binds `texture` to texture unit `unit` and points the sampler at it.
  template <gl_storable T>
  void bind(sampler_id<T> sampler, const texture2d<T>& texture, int unit) const {
    detail::bind_sampler(id(), sampler.location, texture.id(), unit);
  }

  // Throws BindingError unless the symbol table of `stage` carries `hash`
  // (a generated handles header checks it was made from these sources).
  void expect_source_hash(Stage stage, std::string_view hash) const;

  // The untyped core of every lookup. With `host` (checked build) the symbol
  // table is consulted first and a missing name or a mismatch throws
  // BindingError; without it (unchecked build) only the driver is asked.
  int locate(Interface interface, std::string_view name, const ValueType* host) const;

 private:
  template <class T, class Mode>
  static std::unique_ptr<ValueType> host_type() {
    if constexpr (Mode::checks) return std::make_unique<ValueType>(value_traits<T>::describe());
    else return nullptr;
  }
  int array_size(std::string_view name) const;
  const Symbol* find(Interface interface, std::string_view name, const StageSymbols** stage) const;
  void check(Interface interface, std::string_view name, const ValueType& host) const;

  detail::Object object_;
  std::string name_;
  std::vector<StageSymbols> stages_;
  DimensionNamer namer_;
  // Locations by name, from the modules, when the program was loaded as
  // SPIR-V (the driver need not know the names).
  std::optional<SpirvInterface> spirv_;
};

}  // namespace safegi::gl
