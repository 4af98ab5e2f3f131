#pragma once
// The typed library's types as GL values: each is described through the typed
// library's reflection (safegi::describe<T>()) and crosses to GL through its
// plain representation (safegi::raw, safegi::matrix). Works in both builds; in
// the unchecked one the descriptions are never consulted.
#include <safegi/typed.hpp>
#include <safegi/typed/reflection.hpp>

#include "safegi/symbol_table/value_traits.hpp"

namespace safegi::gl {

namespace detail {

inline Kind kind_of(type_kind kind) {
  switch (kind) {
    case type_kind::scalar: return Kind::scalar;
    case type_kind::spectrum: return Kind::spectrum;
    case type_kind::point: return Kind::point;
    case type_kind::vector: return Kind::vector;
    case type_kind::direction: return Kind::direction;
    case type_kind::normal: return Kind::normal;
    case type_kind::hpoint: return Kind::hpoint;
    case type_kind::map: return Kind::map;
    case type_kind::projective_map: return Kind::projective_map;
    default: return Kind::plain;  // rays and frames have no GL value
  }
}

inline ValueType from_description(const type_description& description, std::string glsl_type) {
  ValueType type{kind_of(description.kind), std::move(glsl_type), {}, {}};
  for (const auto& term : description.dimension) type.dimension.exponents[std::string(term.base)] = term.exponent;
  type.dimension.name = std::string(description.dimension_name);
  type.dimension.name_is_hint = true;
  if (!description.space.empty()) type.spaces.emplace_back(description.space);
  if (!description.target_space.empty()) type.spaces.emplace_back(description.target_space);
  return type;
}

// A typed value whose plain representation (safegi::raw) is GL data G.
template <class T, gl_data G>
struct raw_traits {
  using gl_type = G;
  static ValueType describe() { return from_description(safegi::describe<T>(), gl_layout<G>::glsl_name()); }
  static G to_gl(const T& value) { return safegi::raw(value); }
  static T from_gl(const G& value) { return safegi::from_raw<T>(value); }
};

// Maps keep their inverse beside the matrix; GL gets the matrix alone.
template <class T>
struct matrix_traits {
  using gl_type = glm::mat4;
  static ValueType describe() { return from_description(safegi::describe<T>(), "mat4"); }
  static glm::mat4 to_gl(const T& value) { return safegi::matrix(value); }
};

}  // namespace detail

template <class D>
struct value_traits<basic_quantity<D, float>> : detail::raw_traits<basic_quantity<D, float>, float> {};
template <class D>
struct value_traits<basic_spectrum<D>> : detail::raw_traits<basic_spectrum<D>, glm::vec3> {};
template <class S>
struct value_traits<basic_point<S>> : detail::raw_traits<basic_point<S>, glm::vec3> {};
template <class S, class D>
struct value_traits<basic_vector<S, D>> : detail::raw_traits<basic_vector<S, D>, glm::vec3> {};
template <class S>
struct value_traits<basic_direction<S>> : detail::raw_traits<basic_direction<S>, glm::vec3> {};
template <class S>
struct value_traits<basic_normal<S>> : detail::raw_traits<basic_normal<S>, glm::vec3> {};
template <class S>
struct value_traits<basic_hpoint<S>> : detail::raw_traits<basic_hpoint<S>, glm::vec4> {};
template <class A, class B>
struct value_traits<basic_map<A, B>> : detail::matrix_traits<basic_map<A, B>> {};
template <class A, class B>
struct value_traits<basic_projective_map<A, B>> : detail::matrix_traits<basic_projective_map<A, B>> {};

}  // namespace safegi::gl
