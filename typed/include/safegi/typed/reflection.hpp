// Run-time descriptions of typed types, so that code which only meets a type at run
// time (the GL runtime matching a C++ uniform against a shader's symbol table) can
// compare dimensions and spaces by name:
//   describe<spectrum<dim::radiance>>()  → {kind spectrum, dimension {energy 1, length -2, ...},
//                                           dimension_name "radiance"}
// In the unchecked build every type collapses to its plain representation, so a
// description carries the kind and the scalar type only (checked == false).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "safegi/typed/frame.hpp"
#include "safegi/typed/map.hpp"
#include "safegi/typed/ray.hpp"
#include "safegi/typed/space.hpp"
#include "safegi/typed/spectrum.hpp"

namespace safegi {
inline namespace SAFEGI_MODE_NAMESPACE {

enum class type_kind { scalar, spectrum, point, vector, direction, normal, hpoint, map, projective_map, ray, frame };
enum class scalar_type { float32, float64 };

constexpr std::string_view to_string(type_kind kind) {
  constexpr std::string_view names[] = {"scalar", "spectrum", "point",          "vector", "direction", "normal",
                                        "hpoint", "map",      "projective_map", "ray",    "frame"};
  return names[static_cast<int>(kind)];
}

struct dimension_term {
  std::string_view base;
  int exponent = 0;
  friend bool operator==(const dimension_term&, const dimension_term&) = default;
};

struct type_description {
  type_kind kind = type_kind::scalar;
  scalar_type scalar = sizeof(real) == 4 ? scalar_type::float32 : scalar_type::float64;
  /// False in the unchecked build: then only kind and scalar are filled in.
  bool checked = is_checked;
  /// Base dimensions and exponents, sorted by base name; empty when dimensionless.
  std::vector<dimension_term> dimension;
  /// "radiance", "brdf or pdf_projected_solid_angle", or the formula ("length^3*time^-1").
  std::string_view dimension_name;
  /// The space of a point, vector, direction, normal, hpoint, ray or frame; a map's source space.
  std::string_view space;
  /// A map's target space; a frame's local space.
  std::string_view target_space;

  friend bool operator==(const type_description&, const type_description&) = default;

  /// The type as the annotation language writes it: "spectrum<radiance>", "map<object, world>".
  [[nodiscard]] std::string to_string() const {
    std::string text(kind == type_kind::scalar ? std::string_view("float") : safegi::to_string(kind));
    if (!checked) return text;
    std::vector<std::string_view> arguments;
    if (!space.empty()) arguments.push_back(space);
    if (!target_space.empty()) arguments.push_back(target_space);
    const bool has_dimension = kind == type_kind::scalar || kind == type_kind::spectrum || kind == type_kind::vector;
    if (has_dimension && !(kind == type_kind::vector && dimension_name == "length")) arguments.push_back(dimension_name);
    if (kind == type_kind::scalar && dimension.empty()) return text;
    if (arguments.empty()) return text;
    text += "<";
    for (std::size_t i = 0; i < arguments.size(); ++i) (text += (i ? ", " : "")) += arguments[i];
    return text + ">";
  }
};

namespace detail {
template <class... Terms>
std::vector<dimension_term> terms_of(safegi::dimension<Terms...>) {
  return {dimension_term{Terms::base::name.view(), Terms::exponent}...};
}

template <class T>
type_description with_dimension(type_kind kind, scalar_type scalar = sizeof(real) == 4 ? scalar_type::float32
                                                                                      : scalar_type::float64) {
  type_description d;
  d.kind = kind;
  d.scalar = scalar;
  if constexpr (is_checked) {
    d.dimension = terms_of(T{});
    d.dimension_name = dimension_name<T>();
  }
  return d;
}
template <class S>
void set_space(type_description& d) {
  if constexpr (is_checked) d.space = S::name.view();
}
template <class S>
void set_target_space(type_description& d) {
  if constexpr (is_checked) d.target_space = S::name.view();
}

template <class T>
struct describer {};
template <std::floating_point T>
struct describer<T> {
  static type_description get() {
    return with_dimension<dim::dimensionless>(type_kind::scalar,
                                              sizeof(T) == 4 ? scalar_type::float32 : scalar_type::float64);
  }
};
template <class D, class T>
struct describer<basic_quantity<D, T>> {
  static type_description get() {
    return with_dimension<D>(type_kind::scalar, sizeof(T) == 4 ? scalar_type::float32 : scalar_type::float64);
  }
};
template <class D>
struct describer<basic_spectrum<D>> {
  static type_description get() { return with_dimension<D>(type_kind::spectrum); }
};
template <class S, class D>
struct describer<basic_vector<S, D>> {
  static type_description get() {
    auto d = with_dimension<D>(type_kind::vector);
    set_space<S>(d);
    return d;
  }
};
template <type_kind Kind, class S>
struct describe_in_space {
  static type_description get() {
    type_description d;
    d.kind = Kind;
    set_space<S>(d);
    return d;
  }
};
template <class S>
struct describer<basic_point<S>> : describe_in_space<type_kind::point, S> {};
template <class S>
struct describer<basic_direction<S>> : describe_in_space<type_kind::direction, S> {};
template <class S>
struct describer<basic_normal<S>> : describe_in_space<type_kind::normal, S> {};
template <class S>
struct describer<basic_hpoint<S>> : describe_in_space<type_kind::hpoint, S> {};
template <class S>
struct describer<basic_ray<S>> : describe_in_space<type_kind::ray, S> {};
template <type_kind Kind, class A, class B>
struct describe_between_spaces {
  static type_description get() {
    type_description d;
    d.kind = Kind;
    set_space<A>(d);
    set_target_space<B>(d);
    return d;
  }
};
template <class A, class B>
struct describer<basic_map<A, B>> : describe_between_spaces<type_kind::map, A, B> {};
template <class A, class B>
struct describer<basic_projective_map<A, B>> : describe_between_spaces<type_kind::projective_map, A, B> {};
template <class S, class L>
struct describer<basic_frame<S, L>> : describe_between_spaces<type_kind::frame, S, L> {};
}  // namespace detail

template <class T>
concept describable = requires { detail::describer<T>::get(); };

/// What T is, at run time.
template <describable T>
type_description describe() {
  return detail::describer<T>::get();
}

}  // namespace SAFEGI_MODE_NAMESPACE
}  // namespace safegi
