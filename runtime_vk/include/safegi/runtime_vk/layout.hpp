#pragma once
// How a host value is laid out in a Vulkan buffer: the GPU types of
// value_traits (shared with runtime_gl: float, int, uint, GLM vectors and
// matrices, and the typed library's types), plus plain structs the host
// declares as std430 structs (a scene's triangles, BVH nodes).
#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <type_traits>

#include "safegi/symbol_table/value_traits.hpp"

namespace safegi::vk {

using gl::gl_data;
using gl::gl_layout;
using gl::gl_layout_of;
using gl::gl_storable;
using gl::gl_type_of;
using gl::gl_value;
using gl::ScalarType;
using gl::value_traits;

// A C++ struct that mirrors a GLSL struct of a std430 (or scalar) block
// member, byte for byte. Say so, and give the GLSL struct's name:
//   template <> struct safegi::vk::std430_struct<Triangle> {
//     static constexpr std::string_view glsl_name = "Triangle";
//   };
// The runtime checks the name and that sizeof(T) is the array stride the
// symbol table gives; the struct's fields are the host's responsibility.
template <class T>
struct std430_struct;

template <class T>
concept host_struct = requires {
  { std430_struct<T>::glsl_name } -> std::convertible_to<std::string_view>;
}
&&std::is_trivially_copyable_v<T>;

// What a buffer or block member can hold.
template <class T>
concept buffer_element = gl_value<T> || host_struct<T>;

// What can also be read back.
template <class T>
concept readable_element = host_struct<T> ||(gl_value<T>&& requires(const gl_type_of<T>& g) {
  { value_traits<T>::from_gl(g) } -> std::convertible_to<T>;
});

namespace detail {

// Bytes of one element of an array of T in a std430 block (std430: a vec3
// takes 16, a mat3's columns are 16 apart). The symbol table's stride must agree.
template <buffer_element T>
constexpr std::uint32_t std430_stride() {
  if constexpr (host_struct<T>) {
    return static_cast<std::uint32_t>(sizeof(T));
  } else {
    using L = gl_layout_of<T>;
    const std::uint32_t column = L::components == 1 ? 4u : L::components == 2 ? 8u : 16u;
    return column * static_cast<std::uint32_t>(L::columns);
  }
}

// Bytes a member of type T takes (a vec3: 12; a mat3 with 16-byte columns: 48).
template <buffer_element T>
constexpr std::uint32_t value_size(std::uint32_t matrix_stride) {
  if constexpr (host_struct<T>) {
    return static_cast<std::uint32_t>(sizeof(T));
  } else {
    using L = gl_layout_of<T>;
    if constexpr (L::columns == 1)
      return 4u * L::components;
    else
      return matrix_stride * L::columns;
  }
}

// Writes one value at `out` (matrices column by column, `matrix_stride` apart).
template <buffer_element T>
void encode(std::byte* out, const T& value, std::uint32_t matrix_stride) {
  if constexpr (host_struct<T>) {
    std::memcpy(out, &value, sizeof(T));
  } else {
    const gl_type_of<T> data = value_traits<T>::to_gl(value);
    using L = gl_layout_of<T>;
    if constexpr (L::columns == 1) {
      std::memcpy(out, &data, sizeof(data));
    } else {
      for (int c = 0; c < L::columns; ++c) std::memcpy(out + c * matrix_stride, &data[c], 4u * L::components);
    }
  }
}

template <readable_element T>
T decode(const std::byte* in, std::uint32_t matrix_stride) {
  if constexpr (host_struct<T>) {
    T value;
    std::memcpy(&value, in, sizeof(T));
    return value;
  } else {
    gl_type_of<T> data{};
    using L = gl_layout_of<T>;
    if constexpr (L::columns == 1) {
      std::memcpy(&data, in, sizeof(data));
    } else {
      for (int c = 0; c < L::columns; ++c) std::memcpy(&data[c], in + c * matrix_stride, 4u * L::components);
    }
    return value_traits<T>::from_gl(data);
  }
}

// What the checked build compares with the symbol table.
struct HostLayout {
  gl::ValueType type;        // as value_traits<T>::describe(); structs: plain, their GLSL name
  std::uint32_t size = 0;    // value_size with the table's matrix stride of 16
  std::uint32_t stride = 0;  // std430_stride
  int columns = 1;
  bool is_struct = false;  // a std430_struct
};

template <buffer_element T>
HostLayout host_layout() {
  HostLayout layout;
  if constexpr (host_struct<T>) {
    layout.type = gl::ValueType{gl::Kind::plain, std::string(std430_struct<T>::glsl_name), {}, {}};
    layout.is_struct = true;
  } else {
    layout.type = value_traits<T>::describe();
    layout.columns = gl_layout_of<T>::columns;
  }
  layout.size = value_size<T>(16);
  layout.stride = std430_stride<T>();
  return layout;
}

template <class T>
struct element_of {
  using type = T;
};
template <class T, std::size_t N>
struct element_of<T[N]> {
  using type = T;
};
template <class T, std::size_t N>
struct element_of<std::array<T, N>> {
  using type = T;
};

}  // namespace detail

}  // namespace safegi::vk

// Compile-time checks of a host struct that mirrors a block, against the
// layout a generated handles header gives (safegi-gl-handles --api vulkan):
//   struct PushHost { float factor; std::uint32_t count; };
//   SAFEGI_VK_EXPECT_MEMBER(PushHost, count, shaders::scale::layout::Push::count);
// fails to compile when the field's type (dimension, space, GLSL type), byte
// offset or size is not the shader's. Arrays: T[N] or std::array<T, N> of the
// member's element type, N * stride bytes.
#define SAFEGI_VK_EXPECT_MEMBER(Host, field, Member)                                                                 \
  static_assert(                                                                                                     \
      std::is_same_v<typename ::safegi::vk::detail::element_of<decltype(Host::field)>::type, typename Member::type>, \
      #Host "::" #field ": the type differs from the shader's " #Member);                                            \
  static_assert(offsetof(Host, field) == Member::offset,                                                             \
                #Host "::" #field ": the offset differs from the shader's " #Member);                                \
  static_assert(sizeof(Host::field) == Member::size, #Host "::" #field ": the size differs from the "                \
                                                                       "shader's " #Member)

// A descriptor set and binding written by hand (raw Vulkan code beside
// runtime_vk), checked against the generated layout at compile time.
#define SAFEGI_VK_EXPECT_SLOT(Block, set_number, binding_number)                                        \
  static_assert(Block::block_slot.set == (set_number) && Block::block_slot.binding == (binding_number), \
                #Block ": the descriptor set or binding differs from the shader's")
