// Dimensions as exponent vectors over base dimensions the user can extend.
//
// A dimension is the type dimension<term<Base, Exponent>...> in canonical form:
// terms sorted by base name, no zero exponents, one term per base. Every operator
// below produces canonical forms, so two dimensions are equal exactly when their
// types are the same (std::same_as). Nothing here depends on the checked/unchecked
// switch: the algebra is pure type computation.
#pragma once

#include <concepts>
#include <type_traits>

#include "safegi/typed/fixed_string.hpp"

namespace safegi {

/// Derive a tag from this to declare a base dimension:
///   struct pixel_base : safegi::base_dimension<"pixel"> {};
/// (or use SAFEGI_BASE_DIMENSION(pixel), which also declares the dimension `pixel`).
template <fixed_string Name>
struct base_dimension {
  static constexpr auto name = Name;
};

template <class B>
concept base_dimension_tag = requires {
  B::name;
  requires std::is_base_of_v<base_dimension<B::name>, B>;
};

template <base_dimension_tag Base, int Exponent>
struct term {
  using base = Base;
  static constexpr int exponent = Exponent;
};

template <class... Terms>
struct dimension {};

namespace detail {
template <class D>
struct is_dimension : std::false_type {};
template <class... Terms>
struct is_dimension<dimension<Terms...>> : std::true_type {};
}  // namespace detail

template <class D>
concept dimension_type = detail::is_dimension<D>::value;

namespace detail {

template <class A, class B>
constexpr int compare_bases() {
  constexpr auto a = A::name.view();
  constexpr auto b = B::name.view();
  if constexpr (a == b) {
    static_assert(std::is_same_v<A, B>, "two different base dimensions share one name");
    return 0;
  } else {
    return a < b ? -1 : 1;
  }
}

template <class T, class D>
struct prepend;
template <class T, class... Ts>
struct prepend<T, dimension<Ts...>> {
  using type = dimension<T, Ts...>;
};

template <class L, class R>
struct merge;

template <int Order, class L, class R>
struct merge_step;

template <class... R>
struct merge<dimension<>, dimension<R...>> {
  using type = dimension<R...>;
};
template <class L0, class... L>
struct merge<dimension<L0, L...>, dimension<>> {
  using type = dimension<L0, L...>;
};
template <class BL, int EL, class... L, class BR, int ER, class... R>
struct merge<dimension<term<BL, EL>, L...>, dimension<term<BR, ER>, R...>>
    : merge_step<compare_bases<BL, BR>(), dimension<term<BL, EL>, L...>,
                 dimension<term<BR, ER>, R...>> {};

template <class BL, int EL, class... L, class BR, int ER, class... R>
struct merge_step<-1, dimension<term<BL, EL>, L...>, dimension<term<BR, ER>, R...>> {
  using type = typename prepend<term<BL, EL>,
                                typename merge<dimension<L...>, dimension<term<BR, ER>, R...>>::type>::type;
};
template <class BL, int EL, class... L, class BR, int ER, class... R>
struct merge_step<1, dimension<term<BL, EL>, L...>, dimension<term<BR, ER>, R...>> {
  using type = typename prepend<term<BR, ER>,
                                typename merge<dimension<term<BL, EL>, L...>, dimension<R...>>::type>::type;
};
template <class B, int EL, class... L, int ER, class... R>
struct merge_step<0, dimension<term<B, EL>, L...>, dimension<term<B, ER>, R...>> {
  static_assert(static_cast<int>(static_cast<long long>(EL) + ER) == static_cast<long long>(EL) + ER, "dimension exponent overflows int: a product or quotient of these dimensions has an exponent outside the int range");
  using rest = typename merge<dimension<L...>, dimension<R...>>::type;
  using type = std::conditional_t<EL + ER == 0, rest, typename prepend<term<B, EL + ER>, rest>::type>;
};

template <class D, int N>
struct scale;
template <class... Terms, int N>
struct scale<dimension<Terms...>, N> {
  using type = std::conditional_t<N == 0, dimension<>, dimension<term<typename Terms::base, Terms::exponent * N>...>>;
};

template <class D, int N>
struct root;
template <class... Terms, int N>
struct root<dimension<Terms...>, N> {
  static constexpr bool exact = ((Terms::exponent % N == 0) && ...);
  // An inexact root keeps the dimension unchanged; callers report the error first.
  using type = std::conditional_t<exact, dimension<term<typename Terms::base, Terms::exponent / N>...>,
                                  dimension<Terms...>>;
};

template <class... Ds>
struct product;
template <>
struct product<> {
  using type = dimension<>;
};
template <class D>
struct product<D> {
  using type = D;
};
template <class D, class E, class... Rest>
struct product<D, E, Rest...> {
  using type = typename product<typename merge<D, E>::type, Rest...>::type;
};

}  // namespace detail

namespace dim {

/// The dimension made of one base dimension to the first power.
template <base_dimension_tag Base>
using of = dimension<term<Base, 1>>;

template <dimension_type... Ds>
using product = typename detail::product<Ds...>::type;

/// D to the integer power N (named pow because `power` is radiant power).
template <dimension_type D, int N>
using pow = typename detail::scale<D, N>::type;

template <dimension_type D>
using inverse = pow<D, -1>;

template <dimension_type A, dimension_type B>
using quotient = product<A, inverse<B>>;

/// True when every exponent of D is a multiple of N (so root<D, N> exists).
template <dimension_type D, int N>
inline constexpr bool has_root = detail::root<D, N>::exact;

template <dimension_type D, int N>
using root = typename detail::root<D, N>::type;

}  // namespace dim

// Value-level spelling of the same algebra: decltype(dim::energy{} / dim::time{}).
template <class... A, class... B>
constexpr dim::product<dimension<A...>, dimension<B...>> operator*(dimension<A...>, dimension<B...>) {
  return {};
}
template <class... A, class... B>
constexpr dim::quotient<dimension<A...>, dimension<B...>> operator/(dimension<A...>, dimension<B...>) {
  return {};
}

/// The base dimensions of the rendering vocabulary (vocabulary.def, shared with shaders
/// and scene files). base::proj is the projected-cosine factor (n·ω) of the rendering equation.
namespace base {
#define VOCABULARY_BASE(name) \
  struct name : base_dimension<#name> {};
#include "safegi/typed/vocabulary.def"
}  // namespace base

/// The rendering vocabulary, from vocabulary.def. Radiometric quantities follow SafeGI:
/// radiance carries 1/(solid_angle·proj), so a BRDF times radiance only becomes
/// irradiance-like once multiplied by a cosine (proj) and a solid angle — a forgotten
/// cosine is a type error. dim::solid_angle_per_projected_area is dω/dA⊥, the
/// inverse-square law (radiometry.hpp).
namespace dim {
/// A dimension by its exponents over the vocabulary's bases, in vocabulary.def's order.
template <int Length, int Time, int Energy, int Angle, int SolidAngle, int Proj>
using of_exponents = product<pow<of<base::length>, Length>, pow<of<base::time>, Time>, pow<of<base::energy>, Energy>,
                             pow<of<base::angle>, Angle>, pow<of<base::solid_angle>, SolidAngle>, pow<of<base::proj>, Proj>>;
#define VOCABULARY_BASE(name) using name = of<base::name>;
#define VOCABULARY_DIMENSION(name, length, time, energy, angle, solid_angle, proj, shader) \
  using name = of_exponents<length, time, energy, angle, solid_angle, proj>;
#define VOCABULARY_SYNONYM(name, same_as) using name = same_as;
#include "safegi/typed/vocabulary.def"
}  // namespace dim

}  // namespace safegi

/// Declares a new base dimension and the dimension made of it, in one line:
///   SAFEGI_BASE_DIMENSION(pixel);   // then quantity<pixel>, dim::product<pixel, dim::length>, ...
#define SAFEGI_BASE_DIMENSION(name)                                \
  struct name##_base : ::safegi::base_dimension<#name> {};         \
  using name = ::safegi::dim::of<name##_base>
