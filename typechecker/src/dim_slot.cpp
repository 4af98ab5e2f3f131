#include "dim_slot.hpp"

#include <algorithm>

namespace safegi::detail {
namespace {

DimTerm as_term(const DimSlot& s) {
  if (s.state == DimSlot::State::generic) return s.term;
  if (s.state == DimSlot::State::known) return DimTerm::of(s.value);
  return {};
}

// Sorted by variable, no zero exponents.
bool normalise(DimTerm& t) {
  std::sort(t.variables.begin(), t.variables.end());
  std::vector<std::pair<DimVarId, std::int32_t>> merged;
  for (const auto& [v, k] : t.variables) {
    if (!merged.empty() && merged.back().first == v) {
      long long sum = static_cast<long long>(merged.back().second) + k;
      if (sum > INT32_MAX || sum < INT32_MIN) return false;
      merged.back().second = static_cast<std::int32_t>(sum);
    } else {
      merged.push_back({v, k});
    }
  }
  std::erase_if(merged, [](const auto& p) { return p.second == 0; });
  t.variables = std::move(merged);
  return true;
}

DimSlot from_term(DimTerm t) {
  if (t.variables.empty()) return DimSlot::known(std::move(t.constant));
  return DimSlot::generic(std::move(t));
}

}  // namespace

void keep_scaled_spelling(DimSlot& product, const DimSlot& a, const DimSlot& b, bool divide) {
  auto plain = [](const DimSlot& d) { return d.state == DimSlot::State::known && d.value.is_dimensionless(); };
  if (product.state != DimSlot::State::known) return;
  if (plain(b) && a.state == DimSlot::State::known) product.spelling = a.spelling;
  else if (!divide && plain(a) && b.state == DimSlot::State::known) product.spelling = b.spelling;
}

void keep_shared_spelling(DimSlot& result, const std::vector<DimSlot>& sources) {
  if (result.state != DimSlot::State::known) return;
  std::optional<std::string> shared;  // "" once two sources disagree or one has no name
  for (const DimSlot& d : sources) {
    if (d.state != DimSlot::State::known || !(d.value == result.value)) continue;
    shared = !shared || *shared == d.spelling ? d.spelling : std::string();
  }
  if (shared) result.spelling = *shared;
}

std::optional<DimSlot> combine(const DimSlot& a, const DimSlot& b, int sign) {
  if (a.state == DimSlot::State::unknown || b.state == DimSlot::State::unknown) return DimSlot::unknown();
  DimTerm ta = as_term(a), tb = as_term(b);
  Checked<Dimension> c = sign > 0 ? multiply(ta.constant, tb.constant) : divide(ta.constant, tb.constant);
  if (!c) return std::nullopt;
  DimTerm out{*c, ta.variables};
  for (const auto& [v, k] : tb.variables) out.variables.push_back({v, sign > 0 ? k : -k});
  if (!normalise(out)) return std::nullopt;
  return from_term(std::move(out));
}

std::optional<DimSlot> raise(const DimSlot& a, long long n) {
  if (a.state == DimSlot::State::unknown) return DimSlot::unknown();
  if (a.state == DimSlot::State::zero) return DimSlot::known(Dimension{});
  DimTerm t = as_term(a);
  Checked<Dimension> c = power(t.constant, n);
  if (!c) return std::nullopt;
  DimTerm out{*c, {}};
  for (const auto& [v, k] : t.variables) {
    long long e = static_cast<long long>(k) * n;
    if (e > INT32_MAX || e < INT32_MIN) return std::nullopt;
    out.variables.push_back({v, static_cast<std::int32_t>(e)});
  }
  if (!normalise(out)) return std::nullopt;
  return from_term(std::move(out));
}

bool same_dimension(const DimSlot& a, const DimSlot& b) {
  const bool a_ok = a.state == DimSlot::State::known || a.state == DimSlot::State::generic;
  const bool b_ok = b.state == DimSlot::State::known || b.state == DimSlot::State::generic;
  if (!a_ok || !b_ok) return false;
  DimTerm ta = as_term(a), tb = as_term(b);
  if (!normalise(ta) || !normalise(tb)) return false;
  return ta.constant == tb.constant && ta.variables == tb.variables;
}

bool consistent(const DimSlot& a, const DimSlot& b) {
  if (a.state == DimSlot::State::unknown || b.state == DimSlot::State::unknown) return true;
  if (a.state == DimSlot::State::zero || b.state == DimSlot::State::zero) return true;
  return same_dimension(a, b);
}

void keep_homogeneous(Type& part, const Type& whole) {
  part.geometry = Geometry::hpoint;
  part.from = whole.from;
  part.weight = whole.weight;
  part.dim = DimSlot::unknown();
}

bool consistent(const SpaceSlot& a, const SpaceSlot& b) {
  if (a.state == SpaceSlot::State::unknown || b.state == SpaceSlot::State::unknown) return true;
  return a == b;
}

}  // namespace safegi::detail
