#include "safegi/dimension_algebra/dimension.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

namespace safegi {
namespace {

constexpr std::int64_t kMin = std::numeric_limits<std::int32_t>::min();
constexpr std::int64_t kMax = std::numeric_limits<std::int32_t>::max();

bool fits(std::int64_t v) { return v >= kMin && v <= kMax; }

DimensionError overflow(BaseId base, std::int64_t exponent, std::int64_t operand) {
  return {DimensionErrorKind::exponent_overflow, base, exponent, operand};
}

// Combines two sorted factor lists exponent-wise: result = a + sign * b.
Checked<Dimension> combine(const Dimension& a, const Dimension& b, std::int64_t sign) {
  std::vector<Factor> out;
  auto fa = a.factors();
  auto fb = b.factors();
  std::size_t i = 0, j = 0;
  while (i < fa.size() || j < fb.size()) {
    BaseId base;
    std::int64_t ea = 0, eb = 0;
    if (j == fb.size() || (i < fa.size() && fa[i].base < fb[j].base)) {
      base = fa[i].base;
      ea = fa[i++].exponent;
    } else if (i == fa.size() || fb[j].base < fa[i].base) {
      base = fb[j].base;
      eb = fb[j++].exponent;
    } else {
      base = fa[i].base;
      ea = fa[i++].exponent;
      eb = fb[j++].exponent;
    }
    std::int64_t sum = ea + sign * eb;  // |values| < 2^32: no int64 overflow
    if (!fits(sum)) return overflow(base, ea, sign * eb);
    if (sum != 0) out.push_back({base, static_cast<std::int32_t>(sum)});
  }
  return Dimension::from_factors(std::move(out));
}

}  // namespace

Dimension Dimension::base(BaseId id, std::int32_t exponent) {
  Dimension d;
  if (exponent != 0) d.factors_.push_back({id, exponent});
  return d;
}

Checked<Dimension> Dimension::from_factors(std::vector<Factor> factors) {
  std::stable_sort(factors.begin(), factors.end(),
                   [](const Factor& x, const Factor& y) { return x.base < y.base; });
  Dimension d;
  for (const Factor& f : factors) {
    if (!d.factors_.empty() && d.factors_.back().base == f.base) {
      std::int64_t sum = std::int64_t{d.factors_.back().exponent} + f.exponent;
      if (!fits(sum)) return overflow(f.base, d.factors_.back().exponent, f.exponent);
      d.factors_.back().exponent = static_cast<std::int32_t>(sum);
    } else {
      d.factors_.push_back(f);
    }
  }
  std::erase_if(d.factors_, [](const Factor& f) { return f.exponent == 0; });
  return d;
}

std::int32_t Dimension::exponent(BaseId id) const {
  auto it = std::lower_bound(factors_.begin(), factors_.end(), id,
                             [](const Factor& f, BaseId b) { return f.base < b; });
  return it != factors_.end() && it->base == id ? it->exponent : 0;
}

std::size_t Dimension::hash() const {
  std::size_t h = 0x9e3779b97f4a7c15ull;
  for (const Factor& f : factors_) {
    std::size_t v = (std::size_t{f.base} << 32) ^ static_cast<std::uint32_t>(f.exponent);
    h ^= v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
  }
  return h;
}

Checked<Dimension> multiply(const Dimension& a, const Dimension& b) { return combine(a, b, 1); }
Checked<Dimension> divide(const Dimension& a, const Dimension& b) { return combine(a, b, -1); }

Checked<Dimension> power(const Dimension& a, std::int64_t n) {
  if (!fits(n) && !a.is_dimensionless()) return overflow(a.factors()[0].base, a.factors()[0].exponent, n);
  std::vector<Factor> out;
  for (const Factor& f : a.factors()) {
    std::int64_t e;
    if (__builtin_mul_overflow(std::int64_t{f.exponent}, n, &e) || !fits(e)) return overflow(f.base, f.exponent, n);
    if (e != 0) out.push_back({f.base, static_cast<std::int32_t>(e)});
  }
  return Dimension::from_factors(std::move(out));
}

Checked<Dimension> root(const Dimension& a, std::int64_t n) {
  if (n <= 0) return DimensionError{DimensionErrorKind::invalid_root, 0, 0, n};
  std::vector<Factor> out;
  for (const Factor& f : a.factors()) {
    if (f.exponent % n != 0) return DimensionError{DimensionErrorKind::not_a_root, f.base, f.exponent, n};
    out.push_back({f.base, static_cast<std::int32_t>(f.exponent / n)});
  }
  return Dimension::from_factors(std::move(out));
}

Checked<Dimension> rational_power(const Dimension& a, std::int64_t num, std::int64_t den) {
  if (den == 0) return DimensionError{DimensionErrorKind::invalid_root, 0, 0, den};
  // Keeping both within int32 makes negation and gcd below well defined.
  if (!fits(num) || !fits(den)) return overflow(a.is_dimensionless() ? 0 : a.factors()[0].base, 0, fits(num) ? den : num);
  if (den < 0) {
    num = -num;
    den = -den;
  }
  std::int64_t g = std::gcd(num, den);
  num /= g;
  den /= g;
  Checked<Dimension> r = root(a, den);
  if (!r) return r;
  return power(*r, num);
}

}  // namespace safegi
