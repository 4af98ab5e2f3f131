#pragma once
// How a host (C++) type travels to GL and what it means there. A type can be
// bound to a shader variable when value_traits<T> describes it:
//   scalar      float, int32 or uint32 components
//   components  rows per column (1..4), columns (1 for vectors, 2..4 for matrices)
//   describe()  the ValueType compared with the shader's declaration
// Plain scalars and GLM vectors/matrices are described here; the typed
// library's types in typed_traits.hpp. Layout: T must be trivially copyable
// and exactly components*columns tightly packed scalars.
#include <cstdint>
#include <glm/glm.hpp>
#include <type_traits>

#include "safegi/runtime_gl/value_type.hpp"

namespace safegi::gl {

enum class ScalarType { float32, int32, uint32 };

template <class T>
struct value_traits;  // no GL representation unless specialized

template <class T>
concept gl_value = requires {
  { value_traits<T>::scalar } -> std::convertible_to<ScalarType>;
  { value_traits<T>::components } -> std::convertible_to<int>;
  { value_traits<T>::columns } -> std::convertible_to<int>;
  { value_traits<T>::describe() } -> std::same_as<ValueType>;
} && std::is_trivially_copyable_v<T> &&
    sizeof(T) == 4u * value_traits<T>::components * value_traits<T>::columns;

namespace detail {

template <ScalarType S, int Components, int Columns>
struct plain_traits {
  static constexpr ScalarType scalar = S;
  static constexpr int components = Components;
  static constexpr int columns = Columns;
  static ValueType describe() { return {Kind::plain, glsl_name(), {}, {}}; }
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

template <> struct value_traits<float> : detail::plain_traits<ScalarType::float32, 1, 1> {};
template <> struct value_traits<std::int32_t> : detail::plain_traits<ScalarType::int32, 1, 1> {};
template <> struct value_traits<std::uint32_t> : detail::plain_traits<ScalarType::uint32, 1, 1> {};
template <int N> struct value_traits<glm::vec<N, float, glm::defaultp>>
    : detail::plain_traits<ScalarType::float32, N, 1> {};
template <int N> struct value_traits<glm::vec<N, std::int32_t, glm::defaultp>>
    : detail::plain_traits<ScalarType::int32, N, 1> {};
template <int N> struct value_traits<glm::vec<N, std::uint32_t, glm::defaultp>>
    : detail::plain_traits<ScalarType::uint32, N, 1> {};
template <int C, int R> struct value_traits<glm::mat<C, R, float, glm::defaultp>>
    : detail::plain_traits<ScalarType::float32, R, C> {};

}  // namespace safegi::gl
