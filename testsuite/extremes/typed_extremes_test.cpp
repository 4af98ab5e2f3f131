// Extremes of the typed C++ library (issue 8): the largest exponents, long
// chains of derived dimensions (one template instantiation per link), and
// quantity<D, double> at the same extremes. Exponent overflow is a compile
// error: testsuite/compile_fail/cases/exponent_overflow*.cpp.
#include <climits>
#include <type_traits>

#include <gtest/gtest.h>

#include <safegi/typed.hpp>

namespace safegi {
namespace {

using huge = dim::pow<dim::length, INT_MAX>;
using tiny = dim::inverse<huge>;

static_assert(std::is_same_v<dim::product<huge, tiny>, dim::dimensionless>);
static_assert(std::is_same_v<dim::quotient<huge, dim::length>, dim::pow<dim::length, INT_MAX - 1>>);
static_assert(std::is_same_v<tiny, dim::pow<dim::length, -INT_MAX>>);
static_assert(std::is_same_v<dim::pow<dim::length, INT_MIN>, dim::product<tiny, dim::inverse<dim::length>>>);

// dimension d_i = d_{i-1} * length, as the language's derived dimensions.
template <int N>
struct chain {
  using type = dim::product<typename chain<N - 1>::type, dim::length>;
};
template <>
struct chain<0> {
  using type = dim::length;
};
// 800 links: below g++'s default -ftemplate-depth of 900.
static_assert(std::is_same_v<chain<800>::type, dim::pow<dim::length, 801>>);

// Every base dimension at once, each near the limit.
using every_base = dim::product<dim::pow<dim::length, INT_MAX>, dim::pow<dim::time, -INT_MAX>,
                                dim::pow<dim::energy, INT_MAX - 1>, dim::pow<dim::angle, 1 - INT_MAX>,
                                dim::pow<dim::solid_angle, INT_MAX / 2>, dim::pow<dim::proj, INT_MIN / 2>>;
static_assert(std::is_same_v<dim::product<every_base, dim::inverse<every_base>>, dim::dimensionless>);

TEST(TypedExtremes, LargestExponentsMultiplyBackToPlainNumbers) {
  auto a = from_raw<quantity<huge>>(2.0f);
  auto b = from_raw<quantity<tiny>>(0.25f);
  quantity<dim::dimensionless> c = a * b;
  EXPECT_EQ(raw(c), 0.5f);
  auto d = from_raw<quantity<every_base, double>>(3.0);
  auto e = from_raw<quantity<dim::inverse<every_base>, double>>(1.0 / 3.0);
  EXPECT_DOUBLE_EQ(raw(d * e), 1.0);
}

TEST(TypedExtremes, LongDerivedChainKeepsValuesInDoubleAndFloat) {
  auto x = from_raw<quantity<chain<800>::type, double>>(1e300);
  auto y = x / from_raw<quantity<chain<799>::type, double>>(1e299);
  static_assert(std::is_same_v<decltype(y), quantity<dim::length, double>>);
  EXPECT_DOUBLE_EQ(raw(y), 10.0);
  auto f = from_raw<quantity<chain<800>::type>>(3e38f);  // the largest float magnitude, typed
  EXPECT_EQ(raw(f / from_raw<quantity<chain<799>::type>>(3e38f)), 1.0f);
}

}  // namespace
}  // namespace safegi
