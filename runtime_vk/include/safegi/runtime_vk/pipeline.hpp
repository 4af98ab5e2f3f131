#pragma once
// A compute pipeline made from SPIR-V and the compiler's symbol table: its
// descriptor set layouts and push-constant range come from the table, and
// every name the host binds is looked up there, once:
//
//   auto factor = pipeline.push_constant<float>("factor");
//   auto input  = pipeline.storage_array<spectrum<dim::radiance>>("Input.values");
//   pipeline.bind(input, buffer);                 // only a storage_buffer<spectrum<radiance>> compiles
//   block_data pc = pipeline.push_constants();
//   pc.set(factor, 2.0f);                         // only a float compiles
//   pipeline.dispatch(pc, groups_x);
//
// In the checked build a lookup compares the C++ type (value_traits<T>, or a
// std430_struct's name and size) with the declaration: kind, GLSL type,
// dimension, spaces, size, array stride; and it finds set, binding and offset
// in the table. A mismatch throws BindingError naming the shader, the member,
// what it expected and what it found. The unchecked build (SAFEGI_VK_UNCHECKED)
// only reads where things are; both issue the same Vulkan calls.
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "safegi/runtime_vk/context.hpp"
#include "safegi/runtime_vk/handles.hpp"
#include "safegi/runtime_vk/layout.hpp"
#include "safegi/runtime_vk/resources.hpp"
#include "safegi/symbol_table/symbol_table.hpp"

namespace safegi::vk {

using gl::Stage;
using gl::StageSymbols;
using gl::SymbolTable;

// One compute stage as the compiler hands it over: the SPIR-V safeglslc -V
// wrote and the symbol table it wrote beside it (shader mode, or a program
// table with a compute stage). `name` labels messages (default: the table's file).
struct ComputeShader {
  std::vector<std::uint32_t> spirv;
  SymbolTable symbols;
  std::string name = {};
};

// Specialization constants, by name (as the table lists them:
// "gl_WorkGroupSize.x" for local_size_x_id) or by constant_id. Values are
// scalars (float, int, uint, bool, or a typed scalar); the checked build
// compares their type with the declaration when the pipeline is made.
class Specialization {
 public:
  struct Entry {
    std::string name;                 // empty when set by id
    std::optional<std::uint32_t> id;  // set when given by id
    std::optional<gl::ValueType> host;
    std::uint32_t bits = 0;
  };

  template <gl_value T, class Mode = build_mode>
  Specialization& set(std::string_view name, const T& value) {
    entries_.push_back({std::string(name), std::nullopt, host_type<T, Mode>(), bits_of(value)});
    return *this;
  }
  template <gl_value T, class Mode = build_mode>
  Specialization& set(std::uint32_t id, const T& value) {
    entries_.push_back({{}, id, host_type<T, Mode>(), bits_of(value)});
    return *this;
  }
  template <class Mode = build_mode>
  Specialization& set(std::string_view name, bool value) {
    entries_.push_back({std::string(name), std::nullopt, bool_type<Mode>(), value ? 1u : 0u});
    return *this;
  }
  template <class Mode = build_mode>
  Specialization& set(std::uint32_t id, bool value) {
    entries_.push_back({{}, id, bool_type<Mode>(), value ? 1u : 0u});
    return *this;
  }
  const std::vector<Entry>& entries() const { return entries_; }

 private:
  template <gl_value T>
  static std::uint32_t bits_of(const T& value) {
    static_assert(gl_layout_of<T>::components == 1 && gl_layout_of<T>::columns == 1,
                  "a specialization constant is a scalar");
    const gl_type_of<T> data = value_traits<T>::to_gl(value);
    std::uint32_t bits = 0;
    std::memcpy(&bits, &data, sizeof(bits));
    return bits;
  }
  template <class T, class Mode>
  static std::optional<gl::ValueType> host_type() {
    if constexpr (Mode::checks)
      return value_traits<T>::describe();
    else
      return std::nullopt;
  }
  template <class Mode>
  static std::optional<gl::ValueType> bool_type() {
    if constexpr (Mode::checks)
      return gl::ValueType{gl::Kind::plain, "bool", {}, {}};
    else
      return std::nullopt;
  }
  std::vector<Entry> entries_;
};

namespace detail {
struct PipelineImpl;
}

// What a lookup is for: decides where the name is searched and what it must be.
enum class Lookup { push_constant, member, array_member, storage_array, image };

// Where a name lives, as the table says.
struct Location {
  descriptor_slot slot;
  std::uint32_t block = 0;
  std::uint32_t offset = 0;
  std::uint32_t stride = 0;
  std::uint32_t count = 0;
  std::uint32_t matrix_stride = 16;
};

class ComputePipeline {
 public:
  // Makes the descriptor set layouts, the push-constant range, the pipeline
  // layout and the pipeline, and one descriptor set per layout. Throws
  // ShaderError (not a Vulkan compute stage, not SPIR-V, the driver refused
  // it) or BindingError (a specialization constant unknown or of another type).
  ComputePipeline(Context& context, ComputeShader shader, Specialization specialization = {});
  ~ComputePipeline();
  ComputePipeline(ComputePipeline&&) noexcept;
  ComputePipeline& operator=(ComputePipeline&&) noexcept;
  ComputePipeline(const ComputePipeline&) = delete;
  ComputePipeline& operator=(const ComputePipeline&) = delete;

  const std::string& name() const;
  const StageSymbols& stage() const;

  // A member of the push-constant block ("factor", or "PC.factor").
  template <buffer_element T, class Mode = build_mode>
  member_id<T> push_constant(std::string_view member) const {
    const Location at = locate(Lookup::push_constant, member, host<T, Mode>().get());
    return {at.offset, at.matrix_stride, at.block};
  }
  // The push-constant block's bytes (its size from the table), all zero.
  block_data push_constants() const;

  // A member of a uniform or storage block: "Block.member" or "instance.member".
  template <buffer_element T, class Mode = build_mode>
  member_id<T> member(std::string_view name) const {
    const Location at = locate(Lookup::member, name, host<T, Mode>().get());
    return {at.offset, at.matrix_stride, at.block};
  }
  template <buffer_element T, class Mode = build_mode>
  array_member_id<T> array_member(std::string_view name) const {
    const Location at = locate(Lookup::array_member, name, host<T, Mode>().get());
    return {at.offset, at.stride, at.count, at.matrix_stride, at.block};
  }
  // A uniform or storage block's bytes, all zero; a runtime-sized last member
  // gets `runtime_count` elements.
  block_data block(std::string_view name, std::size_t runtime_count = 0) const;
  block_binding_id block_binding(std::string_view name) const;

  // A storage block that is one array of T ("Block.member": its only member).
  template <buffer_element T, class Mode = build_mode>
  storage_array_id<T> storage_array(std::string_view name) const {
    const Location at = locate(Lookup::storage_array, name, host<T, Mode>().get());
    return {at.slot, at.stride};
  }
  // A storage image (image2D) whose texels the host reads and writes as T.
  template <gl_storable T, class Mode = build_mode>
  image_id<T> image(std::string_view name) const {
    const Location at = locate(Lookup::image, name, host<T, Mode>().get());
    return {at.slot};
  }

  // Points the descriptor at the resource (vkUpdateDescriptorSets). A block
  // buffer smaller than the block throws ResourceError.
  void bind(block_binding_id id, const block_buffer& buffer);
  template <buffer_element T>
  void bind(storage_array_id<T> id, const storage_buffer<T>& buffer) {
    bind_buffer(id.slot, buffer.raw());
  }
  template <gl_storable T>
  void bind(image_id<T> id, const image2d<T>& image) {
    bind_image(id.slot, image.raw());
  }

  // Records, submits and waits for one dispatch of x*y*z workgroups. Throws
  // BindingError when a descriptor of the layout is unbound, or push
  // constants are missing or of another pipeline's block.
  void dispatch(std::uint32_t x, std::uint32_t y = 1, std::uint32_t z = 1) const;
  void dispatch(const block_data& push_constants, std::uint32_t x, std::uint32_t y = 1, std::uint32_t z = 1) const;

  // Throws BindingError unless the symbol table carries `hash` (a generated
  // handles header checks it was made from this shader).
  void expect_source_hash(std::string_view hash) const;

  // The untyped core of every lookup. With `host` (checked build) the type is
  // compared too; without (unchecked build) only the location is read.
  Location locate(Lookup lookup, std::string_view name, const detail::HostLayout* host) const;
  void bind_buffer(descriptor_slot slot, const detail::Buffer& buffer);
  void bind_image(descriptor_slot slot, const detail::Image& image);

 private:
  template <class T, class Mode>
  static std::unique_ptr<detail::HostLayout> host() {
    if constexpr (Mode::checks)
      return std::make_unique<detail::HostLayout>(detail::host_layout<T>());
    else
      return nullptr;
  }
  std::unique_ptr<detail::PipelineImpl> impl_;
};

// Reads a SPIR-V file (what safeglslc -V -o x.spv wrote). Throws ShaderError.
std::vector<std::uint32_t> read_spirv_file(const std::string& path);
// Reads a symbol table file (safeglslc --symbols). Throws SymbolTableError.
SymbolTable read_symbol_table_file(const std::string& path);

}  // namespace safegi::vk
