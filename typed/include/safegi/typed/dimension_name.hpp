// Dimensions in words: "radiance" for a dimension of the vocabulary, otherwise the
// canonical product of base powers, e.g. "energy*length^-1*time^-1", for printing and
// reflection; and the vocabulary as types (named::radiance), by which compile errors
// name dimensions (diagnose.hpp).
#pragma once

#include <string_view>

#include "safegi/typed/dimension.hpp"

// The vocabulary's dimensions as types: compile errors name dimensions by these
// (diagnose.hpp), since clang 14 prints string template arguments as character codes.
namespace safegi::named {
#define VOCABULARY_BASE(name) struct name;
#define VOCABULARY_DIMENSION(name, length, time, energy, angle, solid_angle, proj, shader) struct name;
#include "safegi/typed/vocabulary.def"
/// A dimension the vocabulary names more than once (brdf and pdf_projected_solid_angle).
template <class... Names>
struct one_of;
}  // namespace safegi::named

namespace safegi {

/// Specialise to give a user dimension a name in diagnostics and reflection:
///   template <> struct safegi::dimension_label<pixel_density> {
///     static constexpr std::string_view name = "pixel_density"; };
template <dimension_type D>
struct dimension_label {};

namespace detail {

/// A vocabulary entry: the dimension, its name as text, and as a type (named::).
template <class D, fixed_string Name, class Tag>
struct named_dimension {};

template <class... Entries>
struct vocabulary_list {};

struct no_dimension {};

// vocabulary.def's bases and dimensions; several names of one dimension are all listed
// ("brdf or pdf_projected_solid_angle"); synonyms are not.
using vocabulary = vocabulary_list<
#define VOCABULARY_BASE(name) named_dimension<dim::name, #name, named::name>,
#define VOCABULARY_DIMENSION(name, length, time, energy, angle, solid_angle, proj, shader) \
  named_dimension<dim::name, #name, named::name>,
#include "safegi/typed/vocabulary.def"
    named_dimension<no_dimension, "", void>>;

template <class D, class Entry>
constexpr void append_if_named(text_buffer&, Entry) {}
template <class D, fixed_string Name, class Tag>
constexpr void append_if_named(text_buffer& names, named_dimension<D, Name, Tag>) {
  if (!names.empty()) names += " or ";
  names += Name.view();
}

template <class D, class... Entries>
constexpr text_buffer vocabulary_names(vocabulary_list<Entries...>) {
  text_buffer names;
  (append_if_named<D>(names, Entries{}), ...);
  return names;
}

template <class Term>
constexpr void append_base_power(text_buffer& text) {
  if (!text.empty()) text += "*";
  text += Term::base::name.view();
  if (Term::exponent != 1) (text += "^") += Term::exponent;
}

template <class... Terms>
constexpr text_buffer formula(dimension<Terms...>) {
  text_buffer text;
  (append_base_power<Terms>(text), ...);
  if (text.empty()) text += "dimensionless";
  return text;
}

template <dimension_type D>
constexpr text_buffer name() {
  if constexpr (requires { dimension_label<D>::name; }) {
    text_buffer text;
    text += dimension_label<D>::name;
    return text;
  } else {
    text_buffer names = vocabulary_names<D>(vocabulary{});
    return names.empty() ? formula(D{}) : names;
  }
}

template <dimension_type D>
inline constexpr auto frozen_formula = freeze([] { return formula(D{}); });
template <dimension_type D>
inline constexpr auto frozen_name = freeze([] { return name<D>(); });

}  // namespace detail

/// The canonical product of base powers ("energy*length^-2*time^-1"); "dimensionless" if empty.
template <dimension_type D>
constexpr std::string_view dimension_formula() {
  return detail::frozen_formula<D>.view();
}

/// The dimension's name: a user label, else the vocabulary name(s), else its formula.
template <dimension_type D>
constexpr std::string_view dimension_name() {
  return detail::frozen_name<D>.view();
}

/// dimension_formula<D>() as a fixed_string (compile-time text).
template <dimension_type D>
inline constexpr auto formula_text = detail::frozen_formula<D>;

/// dimension_name<D>() as a fixed_string (compile-time text).
template <dimension_type D>
inline constexpr auto dimension_text = detail::frozen_name<D>;

}  // namespace safegi
