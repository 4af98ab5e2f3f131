#pragma once
// How a host (C++) type travels to the GPU (OpenGL, Vulkan) and what it means
// there; shared by runtime_gl and runtime_vk.
//
// gl_layout<G> describes plain GL data G (float, int32, uint32, GLM vectors and
// matrices): scalar type, components per column, columns, GLSL name.
//
// value_traits<T> makes a host type T bindable:
//   using gl_type = G;                  its GL representation (has a gl_layout)
//   static ValueType describe();        compared with the shader's declaration
//   static G to_gl(const T&);           leaving the typed world, explicitly
//   static T from_gl(const G&);         (for read-back)
// Plain GL data is its own representation; the typed library's types are
// described in typed_traits.hpp; tests and users can add their own.
#include <bit>
#include <concepts>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <type_traits>

#include "safegi/symbol_table/value_type.hpp"

namespace safegi::gl {

enum class ScalarType { float32, int32, uint32 };

template <class G>
struct gl_layout;  // not GL data unless specialized

namespace detail {

template <ScalarType S, int Components, int Columns>
struct layout {
  static constexpr ScalarType scalar = S;
  static constexpr int components = Components;
  static constexpr int columns = Columns;
  static std::string glsl_name() {
    if constexpr (Columns > 1) {
      return Columns == Components ? "mat" + std::to_string(Columns)
                                   : "mat" + std::to_string(Columns) + 'x' + std::to_string(Components);
    } else {
      constexpr const char* prefix = S == ScalarType::float32 ? "" : S == ScalarType::int32 ? "i" : "u";
      constexpr const char* scalar_name = S == ScalarType::float32 ? "float" : S == ScalarType::int32 ? "int" : "uint";
      return Components == 1 ? std::string(scalar_name) : prefix + std::string("vec") + std::to_string(Components);
    }
  }
};

}  // namespace detail

template <> struct gl_layout<float> : detail::layout<ScalarType::float32, 1, 1> {};
template <> struct gl_layout<std::int32_t> : detail::layout<ScalarType::int32, 1, 1> {};
template <> struct gl_layout<std::uint32_t> : detail::layout<ScalarType::uint32, 1, 1> {};
template <int N> struct gl_layout<glm::vec<N, float, glm::defaultp>> : detail::layout<ScalarType::float32, N, 1> {};
template <int N> struct gl_layout<glm::vec<N, std::int32_t, glm::defaultp>> : detail::layout<ScalarType::int32, N, 1> {};
template <int N> struct gl_layout<glm::vec<N, std::uint32_t, glm::defaultp>> : detail::layout<ScalarType::uint32, N, 1> {};
template <int C, int R> struct gl_layout<glm::mat<C, R, float, glm::defaultp>> : detail::layout<ScalarType::float32, R, C> {};

template <class G>
concept gl_data = requires {
  { gl_layout<G>::components } -> std::convertible_to<int>;
} && std::is_trivially_copyable_v<G> && sizeof(G) == 4u * gl_layout<G>::components * gl_layout<G>::columns;

template <class T>
struct value_traits;  // no GL meaning unless specialized

// Plain GL data: unannotated in the shader.
template <gl_data G>
struct value_traits<G> {
  using gl_type = G;
  static ValueType describe() { return {Kind::plain, gl_layout<G>::glsl_name(), {}, {}}; }
  static G to_gl(const G& value) { return value; }
  static G from_gl(const G& value) { return value; }
};

template <class T>
concept gl_value = requires(const T& value) {
  typename value_traits<T>::gl_type;
  requires gl_data<typename value_traits<T>::gl_type>;
  { value_traits<T>::describe() } -> std::same_as<ValueType>;
  { value_traits<T>::to_gl(value) } -> std::convertible_to<typename value_traits<T>::gl_type>;
};

template <gl_value T>
using gl_type_of = typename value_traits<T>::gl_type;
template <gl_value T>
using gl_layout_of = gl_layout<gl_type_of<T>>;

// A value whose bytes are its GL representation, so arrays of it go to
// buffers and textures (and come back) without conversion.
template <class T>
concept gl_storable = gl_value<T> && std::is_trivially_copyable_v<T> && sizeof(T) == sizeof(gl_type_of<T>) &&
                      requires(const gl_type_of<T>& g) {
                        { value_traits<T>::from_gl(g) } -> std::convertible_to<T>;
                      };

namespace detail {

// value_traits for a type that is G bit for bit (test stand-ins, user structs).
template <class T, gl_data G>
  requires(sizeof(T) == sizeof(G) && std::is_trivially_copyable_v<T>)
struct bitwise_traits {
  using gl_type = G;
  static G to_gl(const T& value) { return std::bit_cast<G>(value); }
  static T from_gl(const G& value) { return std::bit_cast<T>(value); }
};

}  // namespace detail

}  // namespace safegi::gl
