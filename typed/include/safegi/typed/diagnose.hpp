// Readable compile errors, on the line that made the mistake.
//
// A mistake is a declaration: beside each operation a mistake could call sits an
// overload that only mistakes select, declared and never defined, whose result type
// is one of the reports below. Reports are declared and never defined either, so the
// user's call itself is ill-formed and both compilers put the error on the user's line:
//   user.cpp:12:16: error: invalid use of incomplete type 'struct safegi::diagnose::
//       dimension_mismatch<safegi::diagnose::op::plus, safegi::named::radiance,
//       safegi::named::irradiance, ...>'                                          (g++)
//   user.cpp:12:14: error: implicit instantiation of undefined template
//       'safegi::diagnose::dimension_mismatch<...>'                              (clang++)
// and the note that follows quotes the report's declaration, whose comment on the
// same line says what to do. Every argument of a report is a type (an operation, a
// named dimension, a space, a geometric kind), never a string, because clang++ prints
// string template arguments as character codes; dimensions the vocabulary does not
// name print as their canonical dimension<term<base::..., N>...>.
//
// Conversions have no result type to carry a report. g++ reports the converting
// constructor's defaulted report parameter on the user's line, naming it; clang++
// reports a default argument where it is written (in the library), so there the
// constructor is marked unavailable with the report's words instead.
#pragma once

#include <limits>
#include <type_traits>

#include "safegi/typed/config.hpp"
#include "safegi/typed/dimension_name.hpp"

// The reports. Keep each declaration and its advice on one line: that line is what
// the compilers quote under the error.
namespace safegi::diagnose {
// clang-format off
template <class Operation, class Left, class Right, class LeftOverRight> struct dimension_mismatch;  // the operands must have one dimension; LeftOverRight is the factor too many (proj^-1: a missing cosine, solid_angle or length^2: a pdf in another measure)
template <class From, class To, class FromOverTo> struct conversion_between_dimensions;  // a value cannot change dimension by assignment; FromOverTo is the factor too many (proj^-1: a missing cosine, solid_angle or length^2: a pdf in another measure)
template <class Kind, class From, class To> struct conversion_between_spaces;  // a value cannot change space by assignment: apply a map<From, To>
template <class Given, class Wanted> struct map_conversion;  // a map<A, B> is never a map between other spaces; inverse(m) turns map<A, B> into map<B, A>
template <class Operation, class Dimension> struct plain_number_with_dimension;  // a plain number has no dimension: give it a unit (2.0f * units::metre) or compare with safegi::zero
template <class Dimension> struct sqrt_of_odd_exponent;  // sqrt needs every exponent of the dimension to be even: its square root is not a dimension
template <class Function, class Dimension> struct argument_is_not_an_angle;  // trigonometric functions take an angle: write degrees as x * units::degree, radians as x * units::radian
template <class Function, class Dimension> struct argument_is_not_dimensionless;  // this function takes a dimensionless argument (a ratio): divide by a quantity of the same dimension first
template <class Quantity, class Unit> struct unit_of_another_dimension;  // a quantity is read only in a unit of its own dimension
template <class Operation, class Left, class Right> struct space_mismatch;  // both operands must be in one space: transform one with a map<A, B> first
template <class Map, class Argument> struct map_applied_to_wrong_space;  // a map<A, B> applies only to values in its source space A
template <class Outer, class Inner> struct maps_do_not_meet;  // maps compose only where spaces meet: map<B, C> * map<A, B> gives map<A, C>
template <class Operation, class Left, class Right> struct representation_mismatch;  // float and double quantities do not mix: convert one, from_raw<quantity<D, double>>(raw(q)), or build both from safegi::real
template <class Space> struct cannot_add_points;  // point + point has no meaning: subtract points to get a vector, or blend them with lerp / barycentric
template <class Function, class Space> struct not_a_frame_space;  // cos_theta and the other polar angles read a frame's local space, where the normal is +z: take frame.to_local(w) first, or dot(n, w) in Space; declare local spaces SAFEGI_NORMAL_FRAME_SPACE(name) or SAFEGI_TANGENT_FRAME_SPACE(name)
template <class Function, class Space> struct azimuth_is_arbitrary;  // a frame built from a normal alone has an arbitrary azimuth, so it is no tangent frame: build it with frame<S, L>::from_tangent(dpdu, n); cos_delta_phi compares azimuths in any frame
template <class Given, class Wanted, class Value> struct orientation_mismatch;  // the value points the other way relative to the shaded point: q - P is away from P, P - q toward it; negate it (-w) if the other one was meant
template <class Wanted, class Value> struct orientation_unknown;  // this parameter needs an orientation: derive the value from the shaded point (q - shaded(p)) or state one, as_away(x) / as_toward(x)
template <class Space> struct shading_normal_as_geometric;  // this needs the true surface's normal: an interpolated or bumped normal leaks light or lets a ray hit the surface it left; face_normal(p0, p1, p2), or geometric(n) for a normal known to be the surface's
template <class Kind, class SpaceOrDimension> struct no_numeric_limits;  // a point, vector, direction, normal or spectrum has no numeric limits (std::numeric_limits would answer zero): take a component's, std::numeric_limits<quantity<D>>::infinity(), and build the value from it
template <class Expected, class Given, class Space> struct wrong_geometric_kind;  // kinds transform differently, so convert explicitly: normalize(v), to_direction(n), to_normal(d), dehomogenize(h), p + v
// clang-format on

/// The operations and functions a report names.
namespace op {
struct plus;
struct minus;
struct plus_assign;
struct minus_assign;
struct times;
struct divide;
struct equal;
struct compare;
struct conversion;
struct min;
struct max;
struct clamp;
struct lerp;
struct atan2;
struct pow;
struct sin;
struct cos;
struct tan;
struct asin;
struct acos;
struct atan;
struct exp;
struct log;
struct dot;
struct cross;
struct reflect;
struct barycentric;
struct to_local;
struct from_local;
struct cos_theta;
struct abs_cos_theta;
struct sin_theta;
struct sin2_theta;
struct cos_phi;
struct sin_phi;
struct cos_delta_phi;
struct from_normal;
struct offset_ray_origin;
}  // namespace op

/// Geometric kinds.
namespace kind {
struct point;
struct vector;
struct vector_to_normalize;  // a vector where a direction is wanted: normalize(v)
struct direction;
struct normal;
struct hpoint;
struct ray;
struct spectrum;
}  // namespace kind

/// Labels for the spaces of map reports, so two mentions of one space say which is which.
template <class From, class To>
struct map;
template <class Map>
struct outer;
template <class Map>
struct inner;
template <class Map>
struct given;
template <class Map>
struct wanted;
template <class Space>
struct argument_in;
}  // namespace safegi::diagnose

namespace safegi {
namespace detail {
template <class... Names>
struct word_list {};

template <class D, class Entry>
struct word_if_same {
  using type = word_list<>;
};
template <class D, fixed_string Name, class Tag>
struct word_if_same<D, named_dimension<D, Name, Tag>> {
  using type = word_list<Tag>;
};
template <class... Lists>
struct join_words;
template <>
struct join_words<> {
  using type = word_list<>;
};
template <class... A, class... Rest>
struct join_words<word_list<A...>, Rest...> {
  template <class Tail>
  struct prepend;
  template <class... B>
  struct prepend<word_list<B...>> {
    using type = word_list<A..., B...>;
  };
  using type = typename prepend<typename join_words<Rest...>::type>::type;
};

template <class D, class Names>
struct words_or_formula {
  using type = D;  // not in the vocabulary: its canonical form, whose bases are words
};
template <class D, class Name>
struct words_or_formula<D, word_list<Name>> {
  using type = Name;
};
template <class D, class First, class Second, class... Rest>
struct words_or_formula<D, word_list<First, Second, Rest...>> {
  using type = named::one_of<First, Second, Rest...>;
};

template <class D, class Vocabulary>
struct words_in;
template <class D, class... Entries>
struct words_in<D, vocabulary_list<Entries...>> {
  using type =
      typename words_or_formula<D, typename join_words<typename word_if_same<D, Entries>::type...>::type>::type;
};
}  // namespace detail

/// A dimension as a report names it: named::radiance, or its canonical form.
template <dimension_type D>
using in_words = typename detail::words_in<D, detail::vocabulary>::type;

/// The factor by which dimension L exceeds R (L/R), as a report names it: proj^-1 is a
/// missing cosine, solid_angle or length^2 a pdf in another measure.
template <dimension_type L, dimension_type R>
using ratio_in_words = in_words<dim::quotient<L, R>>;
}  // namespace safegi

namespace safegi::diagnose {
// A report that names dimensions in words is formed only for the mistake itself. Forming
// one means searching the vocabulary for each dimension it names, so a declaration that
// formed it for every use (a class's member template instantiated with the class, a
// converting constructor's defaulted Report, a mistake's return type when the rule holds)
// made every checked program pay for its reports. An overload for a mistake therefore
// names its report through report_if<Mistake, Words>::type, which is Words::type where
// Mistake holds and names nothing (so the overload drops out, cheaply) where it does not;
// the free overloads also require the rule's negation, which g++ checks before forming
// their result type. The words_* below form the reports of diagnose:: above.
template <bool Mistake, class Words>
struct report_if {};
template <class Words>
struct report_if<true, Words> {
  using type = typename Words::type;
};
template <class Operation, class L, class R>
struct words_dimension_mismatch {
  using type = dimension_mismatch<Operation, in_words<L>, in_words<R>, ratio_in_words<L, R>>;
};
template <class From, class To>
struct words_conversion_between_dimensions {
  using type = conversion_between_dimensions<in_words<From>, in_words<To>, ratio_in_words<From, To>>;
};
template <class Operation, class D>
struct words_plain_number_with_dimension {
  using type = plain_number_with_dimension<Operation, in_words<D>>;
};
}  // namespace safegi::diagnose

namespace safegi {
namespace diagnose {
/// What std::numeric_limits says of a geometric kind: nothing. The primary template would
/// answer point<S>() (the origin) for infinity(); each question is a report instead.
template <class Kind, class Of>
struct refused_numeric_limits {
  static constexpr bool is_specialized = false;
  static diagnose::no_numeric_limits<Kind, Of> min() noexcept;
  static diagnose::no_numeric_limits<Kind, Of> max() noexcept;
  static diagnose::no_numeric_limits<Kind, Of> lowest() noexcept;
  static diagnose::no_numeric_limits<Kind, Of> epsilon() noexcept;
  static diagnose::no_numeric_limits<Kind, Of> round_error() noexcept;
  static diagnose::no_numeric_limits<Kind, Of> infinity() noexcept;
  static diagnose::no_numeric_limits<Kind, Of> quiet_NaN() noexcept;
  static diagnose::no_numeric_limits<Kind, Of> signaling_NaN() noexcept;
  static diagnose::no_numeric_limits<Kind, Of> denorm_min() noexcept;
};
}  // namespace diagnose
}  // namespace safegi

// A converting constructor that only mistakes select is declared with its report as a
// defaulted template parameter named Report:
//   template <class Other, class Report = diagnose::report<...>>
//   SAFEGI_MISTAKE basic_x(basic_x<Other> SAFEGI_REPORTED_AS(Report))
//       SAFEGI_SAYS("words");
// g++ reports the defaulted parameter of the report's type on the user's line, naming the
// report. clang++ would report that default argument inside the library, so there the
// constructor is consteval instead, and its body calls a function that is not constexpr:
// clang++ reports on the user's line that the call "to consteval function
// 'basic_x<...>::basic_x<Other, safegi::diagnose::report<...>>' is not a constant
// expression" (the report, with both dimensions or spaces named, in the function's
// template arguments), then quotes the SAFEGI_SAYS line, words included.
#if defined(__clang__)
#define SAFEGI_MISTAKE consteval
#define SAFEGI_REPORTED_AS(...)
#define SAFEGI_SAYS(words) \
  { ::safegi::diagnose::reported<Report>(); }
#else
#define SAFEGI_MISTAKE
#define SAFEGI_REPORTED_AS(...) , __VA_ARGS__ = {}
#define SAFEGI_SAYS(words)
#endif

namespace safegi::diagnose {
/// Not constexpr, and never defined: a consteval mistake that calls it is refused at the call.
template <class Report>
void reported();
}  // namespace safegi::diagnose

namespace safegi {
namespace space_detail {
struct frame_space_marker;
struct tangent_frame_marker;
}  // namespace space_detail
inline namespace SAFEGI_MODE_NAMESPACE {
namespace rules {

// What the operations ask of their operands. Each holds in the unchecked build, so a
// report is never chosen there. An operation requires these concepts; its report overload
// requires a rule's negation where the report names dimensions in words (so a valid call
// never forms it, report_if above), and otherwise less, so where both are viable the
// operation is more constrained.
template <class Left, class Right>
concept same_dimension = !is_checked || std::is_same_v<Left, Right>;
template <class Left, class Right>
concept same_space = !is_checked || std::is_same_v<Left, Right>;
template <class D>
concept dimensionless = !is_checked || std::is_same_v<D, dim::dimensionless>;
template <class D>
concept angle = !is_checked || std::is_same_v<D, dim::angle>;
template <class D>
concept even_exponents = !is_checked || dim::has_root<D, 2>;
/// A frame's local space (SAFEGI_NORMAL_FRAME_SPACE or SAFEGI_TANGENT_FRAME_SPACE).
template <class S>
concept frame_space = !is_checked || std::is_base_of_v<::safegi::space_detail::frame_space_marker, S>;
/// A tangent frame's local space (+x along dp/du).
template <class S>
concept tangent_frame_space = !is_checked || std::is_base_of_v<::safegi::space_detail::tangent_frame_marker, S>;
/// The local space of a frame built from a normal alone: a frame space, not a tangent one.
template <class S>
concept normal_frame_space =
    !is_checked || (std::is_base_of_v<::safegi::space_detail::frame_space_marker, S> && !std::is_base_of_v<::safegi::space_detail::tangent_frame_marker, S>);

}  // namespace rules
}  // namespace SAFEGI_MODE_NAMESPACE
}  // namespace safegi
