#pragma once
// A physical dimension: a product of integer powers of named base dimensions,
// stored sparsely (only non-zero exponents, sorted by base id). Dimensions form
// an Abelian group under multiplication; every operation that could overflow
// the int32 exponents reports an error value instead of wrapping.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace safegi {

using BaseId = std::uint32_t;

struct Factor {
  BaseId base = 0;
  std::int32_t exponent = 0;
  friend bool operator==(const Factor&, const Factor&) = default;
};

enum class DimensionErrorKind {
  exponent_overflow,  // an exponent left the int32 range
  not_a_root,         // root(D, n) where some exponent is not divisible by n
  invalid_root,       // root of degree 0 or negative degree
};

struct DimensionError {
  DimensionErrorKind kind = DimensionErrorKind::exponent_overflow;
  BaseId base = 0;             // the offending base (not meaningful for invalid_root)
  std::int64_t exponent = 0;   // its exponent before the failing operation
  std::int64_t operand = 0;    // the multiplier, divisor or root degree involved
  friend bool operator==(const DimensionError&, const DimensionError&) = default;
};

// The result of a fallible operation: a value or the reason it has none.
template <class T>
class Checked {
 public:
  Checked(T value) : state_(std::move(value)) {}                // NOLINT: implicit by design
  Checked(DimensionError error) : state_(std::move(error)) {}   // NOLINT
  bool ok() const { return std::holds_alternative<T>(state_); }
  explicit operator bool() const { return ok(); }
  const T& value() const { return std::get<T>(state_); }
  const T& operator*() const { return value(); }
  const T* operator->() const { return &value(); }
  const DimensionError& error() const { return std::get<DimensionError>(state_); }

 private:
  std::variant<T, DimensionError> state_;
};

class Dimension {
 public:
  Dimension() = default;  // dimensionless
  static Dimension base(BaseId id, std::int32_t exponent = 1);
  // Merges repeated bases and drops zero exponents; overflow while merging is reported.
  static Checked<Dimension> from_factors(std::vector<Factor> factors);

  std::span<const Factor> factors() const { return factors_; }
  std::int32_t exponent(BaseId id) const;
  bool is_dimensionless() const { return factors_.empty(); }

  friend bool operator==(const Dimension&, const Dimension&) = default;
  std::size_t hash() const;

 private:
  std::vector<Factor> factors_;  // sorted by base, no zero exponents
};

Checked<Dimension> multiply(const Dimension& a, const Dimension& b);
Checked<Dimension> divide(const Dimension& a, const Dimension& b);
Checked<Dimension> power(const Dimension& a, std::int64_t n);
// The n-th root: every exponent must be divisible by n (sqrt is root(d, 2)).
Checked<Dimension> root(const Dimension& a, std::int64_t n);
// a^(num/den), exact: root first, so a^(2/2) of an odd exponent still fails cleanly.
Checked<Dimension> rational_power(const Dimension& a, std::int64_t num, std::int64_t den);

}  // namespace safegi

template <>
struct std::hash<safegi::Dimension> {
  std::size_t operator()(const safegi::Dimension& d) const noexcept { return d.hash(); }
};
