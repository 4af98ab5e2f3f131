#include "safegi/dimension_algebra/dimension.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <unordered_set>

namespace safegi {
namespace {

const Dimension L = Dimension::base(0);
const Dimension T = Dimension::base(1);
const Dimension E = Dimension::base(2);

Dimension mul(const Dimension& a, const Dimension& b) { return *multiply(a, b); }
Dimension div(const Dimension& a, const Dimension& b) { return *divide(a, b); }

TEST(Dimension, DimensionlessIsTheIdentity) {
  Dimension one;
  EXPECT_TRUE(one.is_dimensionless());
  EXPECT_EQ(mul(L, one), L);
  EXPECT_EQ(mul(one, L), L);
  EXPECT_EQ(div(L, one), L);
}

TEST(Dimension, GroupLaws) {
  const Dimension a = mul(L, T), b = div(E, L), c = *power(T, -3);
  EXPECT_EQ(mul(mul(a, b), c), mul(a, mul(b, c)));  // associative
  EXPECT_EQ(mul(a, b), mul(b, a));                  // commutative
  EXPECT_EQ(mul(a, *power(a, -1)), Dimension{});    // inverse
  EXPECT_EQ(div(a, a), Dimension{});
  EXPECT_EQ(div(a, b), mul(a, *power(b, -1)));
}

TEST(Dimension, FactorsAreSortedAndSparse) {
  const Dimension d = mul(mul(E, L), div(T, T));
  ASSERT_EQ(d.factors().size(), 2u);
  EXPECT_EQ(d.factors()[0], (Factor{0, 1}));
  EXPECT_EQ(d.factors()[1], (Factor{2, 1}));
  EXPECT_EQ(d.exponent(1), 0);
  EXPECT_EQ(d.exponent(2), 1);
  EXPECT_EQ(d.exponent(99), 0);
}

TEST(Dimension, FromFactorsMergesAndDropsZeros) {
  auto d = Dimension::from_factors({{2, 1}, {0, 2}, {2, -1}, {0, 1}});
  ASSERT_TRUE(d);
  EXPECT_EQ(*d, *power(L, 3));
}

TEST(Dimension, PowerAndRoot) {
  const Dimension area = *power(L, 2);
  EXPECT_EQ(*root(area, 2), L);
  EXPECT_EQ(*power(area, 0), Dimension{});
  EXPECT_EQ(*root(Dimension{}, 7), Dimension{});
  EXPECT_EQ(*rational_power(*power(L, 3), 2, 3), area);
  EXPECT_EQ(*rational_power(*power(L, 2), -1, -2), L);
}

TEST(Dimension, RootOfOddExponentNamesTheBase) {
  const Dimension d = mul(*power(L, 2), *power(T, 3));
  auto r = root(d, 2);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().kind, DimensionErrorKind::not_a_root);
  EXPECT_EQ(r.error().base, 1u);
  EXPECT_EQ(r.error().exponent, 3);
  EXPECT_EQ(r.error().operand, 2);
  EXPECT_FALSE(rational_power(L, 1, 2));
  EXPECT_EQ(root(L, 0).error().kind, DimensionErrorKind::invalid_root);
  EXPECT_EQ(rational_power(L, 1, 0).error().kind, DimensionErrorKind::invalid_root);
}

TEST(Dimension, RepeatedSquaringOverflowIsReported) {
  Dimension d = L;
  int steps = 0;
  for (;;) {
    auto next = multiply(d, d);
    if (!next) {
      EXPECT_EQ(next.error().kind, DimensionErrorKind::exponent_overflow);
      EXPECT_EQ(next.error().base, 0u);
      EXPECT_EQ(next.error().exponent, std::int64_t{1} << 30);
      break;
    }
    d = *next;
    ++steps;
  }
  EXPECT_EQ(steps, 30);
  EXPECT_EQ(d.exponent(0), 1 << 30);
}

TEST(Dimension, ExtremeExponents) {
  const std::int32_t max = std::numeric_limits<std::int32_t>::max();
  const std::int32_t min = std::numeric_limits<std::int32_t>::min();
  const Dimension big = Dimension::base(0, max);
  const Dimension small = Dimension::base(0, min);
  EXPECT_FALSE(multiply(big, L));
  EXPECT_FALSE(divide(small, L));
  EXPECT_FALSE(power(small, -1));  // -INT32_MIN does not fit
  EXPECT_EQ(*power(big, -1), Dimension::base(0, -max));
  EXPECT_EQ(*divide(big, big), Dimension{});
  EXPECT_FALSE(power(L, std::int64_t{1} << 40));
  EXPECT_FALSE(power(big, std::numeric_limits<std::int64_t>::min()));
  EXPECT_EQ(*power(Dimension{}, std::int64_t{1} << 40), Dimension{});
  EXPECT_FALSE(rational_power(L, std::numeric_limits<std::int64_t>::min(), 1));
  EXPECT_EQ(*root(small, 2), Dimension::base(0, min / 2));
  EXPECT_FALSE(Dimension::from_factors({{0, max}, {0, 1}}));
}

TEST(Dimension, HashAgreesWithEquality) {
  std::unordered_set<Dimension> set;
  set.insert(mul(L, T));
  set.insert(mul(T, L));
  set.insert(div(L, T));
  set.insert(Dimension{});
  EXPECT_EQ(set.size(), 3u);
  EXPECT_NE(mul(L, T).hash(), div(L, T).hash());
}

}  // namespace
}  // namespace safegi
