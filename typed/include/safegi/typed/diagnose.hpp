// Readable compile errors. Each mistake instantiates one of these reports with the
// involved dimensions and spaces spelled as strings; g++ starts its error with
//   In instantiation of 'struct safegi::diagnose::dimension_mismatch<
//       safegi::fixed_string<2>{"+"}, safegi::fixed_string<9>{"radiance"},
//       safegi::fixed_string<11>{"irradiance"}>':
// and then prints the static_assert message below, so both sides are named in words
// before any template machinery appears.
#pragma once

#include <type_traits>

#include "safegi/typed/config.hpp"
#include "safegi/typed/dimension_name.hpp"

namespace safegi::diagnose {

template <auto...>
inline constexpr bool reported = false;

// Ratio is left / right (from / to) as a formula: proj^-1 is a missing cosine, a power
// of solid_angle or length a pdf in the wrong measure.
template <fixed_string Operation, fixed_string Left, fixed_string Right, fixed_string Ratio>
struct dimension_mismatch {
  static_assert(reported<Operation, Left, Right, Ratio>,
                "dimension mismatch: the operands of this operation must have the same dimension "
                "(operation, left and right dimension, and left/right, are named above)");
};

template <fixed_string From, fixed_string To, fixed_string Ratio>
struct conversion_between_dimensions {
  static_assert(reported<From, To, Ratio>,
                "cannot convert a value of one dimension into another (from and to dimension, and "
                "from/to, are named above): the ratio from/to is the factor too many, e.g. proj^-1 a "
                "missing cosine, solid_angle or length^2 a pdf in another measure");
};

template <fixed_string Kind, fixed_string From, fixed_string To>
struct conversion_between_spaces {
  static_assert(reported<Kind, From, To>,
                "cannot convert a value from one space into another by assignment (kind, from and to "
                "space are named above): apply a map<From, To>");
};

template <fixed_string Given, fixed_string Wanted>
struct map_conversion {
  static_assert(reported<Given, Wanted>,
                "cannot convert map<A, B> into a map between other spaces (the given and the wanted map "
                "are named above); inverse(m) turns map<A, B> into map<B, A>");
};

template <fixed_string Operation, fixed_string Dimension>
struct plain_number_with_dimension {
  static_assert(reported<Operation, Dimension>,
                "a plain number has no dimension and cannot be added to or compared with a quantity "
                "that has one: give the number a unit (2.0f * units::metre) or compare with safegi::zero");
};

template <fixed_string Dimension>
struct sqrt_of_odd_exponent {
  static_assert(reported<Dimension>,
                "sqrt needs every exponent of the dimension to be even (the dimension is named above); "
                "its square root is not a dimension");
};

template <fixed_string Function, fixed_string Dimension>
struct argument_is_not_an_angle {
  static_assert(reported<Function, Dimension>,
                "trigonometric functions take an angle (quantity<dim::angle>): write degrees as "
                "x * units::degree and radians as x * units::radian");
};

template <fixed_string Function, fixed_string Dimension>
struct argument_is_not_dimensionless {
  static_assert(reported<Function, Dimension>,
                "this function needs a dimensionless argument (the argument's dimension is named above)");
};

template <fixed_string Quantity, fixed_string Unit>
struct unit_of_another_dimension {
  static_assert(reported<Quantity, Unit>,
                "a quantity can only be expressed in a unit of its own dimension "
                "(quantity and unit dimensions are named above)");
};

template <fixed_string Operation, fixed_string Left, fixed_string Right>
struct space_mismatch {
  static_assert(reported<Operation, Left, Right>,
                "space mismatch: both operands must be in the same space; transform one with a "
                "map<A, B> first (operation, left and right space are named above)");
};

template <fixed_string Map, fixed_string Argument>
struct map_applied_to_wrong_space {
  static_assert(reported<Map, Argument>,
                "a map<A, B> only applies to values in its source space A "
                "(the map and the argument's space are named above)");
};

template <fixed_string Outer, fixed_string Inner>
struct maps_do_not_meet {
  static_assert(reported<Outer, Inner>,
                "maps compose only where spaces meet: map<B, C> * map<A, B> gives map<A, C> "
                "(the outer and the inner map are named above)");
};

template <fixed_string Operation, fixed_string Left, fixed_string Right>
struct representation_mismatch {
  static_assert(reported<Operation, Left, Right>,
                "the operands hold different representations (named above): convert one explicitly, "
                "from_raw<quantity<D, double>>(raw(q)), or build both from safegi::real");
};

template <fixed_string Space>
struct cannot_add_points {
  static_assert(reported<Space>,
                "two points cannot be added (point + point has no meaning in affine space): "
                "subtract them to get a vector, or use lerp / barycentric to blend points");
};

template <fixed_string Expected, fixed_string Given, fixed_string Space>
struct wrong_geometric_kind {
  static_assert(reported<Expected, Given, Space>,
                "wrong kind of geometric value (expected kind, given kind and its space are named above): "
                "points, vectors, directions, normals and hpoints transform differently, so convert "
                "explicitly: normalize(v), to_direction(n), to_normal(d), dehomogenize(h), p + v");
};

}  // namespace safegi::diagnose

// The checks that raise the reports. They live in the mode namespace because the
// unchecked build turns every one of them into a no-op.
namespace safegi {
inline namespace SAFEGI_MODE_NAMESPACE {
namespace rules {

/// "float" or "double", for reports about mixed representations.
template <class T>
struct representation_name {
  static constexpr auto text = fixed_string("long double");
};
template <>
struct representation_name<float> {
  static constexpr auto text = fixed_string("float");
};
template <>
struct representation_name<double> {
  static constexpr auto text = fixed_string("double");
};
template <class T>
inline constexpr auto representation_text = representation_name<T>::text;

template <fixed_string Operation, dimension_type Left, dimension_type Right>
constexpr void same_dimension() {
  if constexpr (is_checked && !std::is_same_v<Left, Right>)
    (void)sizeof(diagnose::dimension_mismatch<Operation, dimension_text<Left>, dimension_text<Right>,
                                              formula_text<dim::quotient<Left, Right>>>);
}

template <dimension_type From, dimension_type To>
constexpr void convertible_dimension() {
  if constexpr (is_checked && !std::is_same_v<From, To>)
    (void)sizeof(diagnose::conversion_between_dimensions<dimension_text<From>, dimension_text<To>,
                                                         formula_text<dim::quotient<From, To>>>);
}

template <fixed_string Kind, class From, class To>
constexpr void convertible_space() {
  if constexpr (is_checked && !std::is_same_v<From, To>)
    (void)sizeof(diagnose::conversion_between_spaces<Kind, From::name, To::name>);
}

template <fixed_string Operation, dimension_type D>
constexpr void number_needs_dimensionless() {
  if constexpr (is_checked && !std::is_same_v<D, dim::dimensionless>)
    (void)sizeof(diagnose::plain_number_with_dimension<Operation, dimension_text<D>>);
}

template <fixed_string Function, dimension_type D>
constexpr void angle() {
  if constexpr (is_checked && !std::is_same_v<D, dim::angle>)
    (void)sizeof(diagnose::argument_is_not_an_angle<Function, dimension_text<D>>);
}

template <fixed_string Function, dimension_type D>
constexpr void dimensionless() {
  if constexpr (is_checked && !std::is_same_v<D, dim::dimensionless>)
    (void)sizeof(diagnose::argument_is_not_dimensionless<Function, dimension_text<D>>);
}

template <dimension_type D>
constexpr void even_exponents() {
  if constexpr (is_checked && !dim::has_root<D, 2>)
    (void)sizeof(diagnose::sqrt_of_odd_exponent<dimension_text<D>>);
}

/// The report for mixing representations (used only by overloads that exist to report it).
template <fixed_string Operation, class Left, class Right>
using representation_report =
    diagnose::representation_mismatch<Operation, representation_text<Left>, representation_text<Right>>;

/// "map<world, camera>": a map's spaces, labelled, for reports that name two maps or a map and a value.
template <class From, class To>
inline constexpr auto map_text = joined_text<"map<", From::name, ", ", To::name, ">">;

template <fixed_string Operation, class Left, class Right>
constexpr void same_space() {
  if constexpr (is_checked && !std::is_same_v<Left, Right>)
    (void)sizeof(diagnose::space_mismatch<Operation, Left::name, Right::name>);
}

}  // namespace rules
}  // namespace SAFEGI_MODE_NAMESPACE
}  // namespace safegi
