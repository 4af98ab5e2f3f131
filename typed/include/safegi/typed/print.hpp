// Printing typed values: the number in its reference unit, the unit, and the dimension
// in words, so a log line says what it holds:
//   std::cout << L;                 // 2 W·m⁻²·sr⁻¹ (radiance)
//   safegi::to_string(p)            // point<world>(1 m, 2 m, 0 m)
// The unit is built from the reference units of the base dimensions (m, s, J, rad, sr;
// energy per time is W); proj has no unit, so it shows only in the dimension's name.
// A user base dimension is shown by its name. The unchecked build has no dimensions or
// spaces left to print: there a quantity is a float and a point prints as point(1, 2, 0).
//
// With a standard library that has <format> (__cpp_lib_format), std::format("{:.2f}", q)
// formats the number with the given spec and appends the same unit and name.
#pragma once

#include <ostream>
#include <sstream>
#include <string>
#include <string_view>

#include "safegi/typed/ray.hpp"
#include "safegi/typed/space.hpp"
#include "safegi/typed/spectrum.hpp"

#if defined(__has_include)
#if __has_include(<version>)
#include <version>
#endif
#endif
#if defined(__cpp_lib_format)
#include <algorithm>
#include <format>
#endif

namespace safegi {
inline namespace SAFEGI_MODE_NAMESPACE {

namespace detail {
/// The symbol of a base dimension's reference unit; proj has none.
inline std::string_view reference_unit_symbol(std::string_view base) {
  if (base == "length") return "m";
  if (base == "time") return "s";
  if (base == "energy") return "J";
  if (base == "angle") return "rad";
  if (base == "solid_angle") return "sr";
  if (base == "proj") return "";
  return base;  // a user base dimension: its own name
}

inline void append_superscript(std::string& text, int exponent) {
  static constexpr std::string_view digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  if (exponent == 1) return;
  if (exponent < 0) text += "⁻";
  const std::string decimal = std::to_string(exponent < 0 ? -static_cast<long long>(exponent) : exponent);
  for (char c : decimal) text += digits[c - '0'];
}

inline void append_unit_power(std::string& text, std::string_view symbol, int exponent) {
  if (symbol.empty() || exponent == 0) return;
  if (!text.empty()) text += "·";
  text += symbol;
  append_superscript(text, exponent);
}

/// Energy and time with opposite exponents print as watts (W·m⁻² rather than J·m⁻²·s⁻¹).
template <class... Terms>
std::string unit_text(dimension<Terms...>) {
  int energy = 0, time = 0;
  ((Terms::base::name.view() == "energy" ? energy = Terms::exponent : 0), ...);
  ((Terms::base::name.view() == "time" ? time = Terms::exponent : 0), ...);
  const int watts = energy != 0 && energy == -time ? energy : 0;
  std::string text;
  append_unit_power(text, "W", watts);
  append_unit_power(text, "J", energy - watts);
  // The remaining bases in the canonical (alphabetical) order, time after them as in SI.
  (
      [&] {
        const std::string_view base = Terms::base::name.view();
        if (base != "energy" && base != "time") append_unit_power(text, reference_unit_symbol(base), Terms::exponent);
      }(),
      ...);
  append_unit_power(text, "s", time + watts);
  return text;
}

/// " W·m⁻²·sr⁻¹ (radiance)": what follows a number of dimension D.
template <dimension_type D>
std::string unit_suffix() {
  std::string unit = unit_text(D{});
  std::string suffix;
  if (!unit.empty()) (suffix += " ") += unit;
  if constexpr (!std::is_same_v<D, dim::dimensionless>) ((suffix += " (") += dimension_name<D>()) += ")";
  return suffix;
}

template <class S>
std::string_view space_label() {
  return is_checked ? std::string_view(S::name.view()) : std::string_view();
}

/// kind<space>(a, b, c): each component followed by `unit` (" m" for a point).
inline void print_components(std::ostream& os, std::string_view kind, std::string_view arguments, const real* xyz,
                             int count, std::string_view unit) {
  os << kind;
  if (!arguments.empty()) os << '<' << arguments << '>';
  os << '(';
  for (int i = 0; i < count; ++i) os << (i ? ", " : "") << xyz[i] << unit;
  os << ')';
}
}  // namespace detail

template <class D, class T>
std::ostream& operator<<(std::ostream& os, basic_quantity<D, T> q) {
  return os << q.raw_value() << detail::unit_suffix<D>();
}

template <class D>
std::ostream& operator<<(std::ostream& os, basic_spectrum<D> s) {
  const vec3_rep rgb = s.raw_value();
  os << '(' << rgb.r << ", " << rgb.g << ", " << rgb.b << ')';
  if constexpr (is_checked) os << detail::unit_suffix<D>();
  return os;
}

template <class S>
std::ostream& operator<<(std::ostream& os, basic_point<S> p) {
  const vec3_rep xyz = p.raw_value();
  detail::print_components(os, "point", detail::space_label<S>(), &xyz.x, 3, is_checked ? " m" : "");
  return os;
}

/// vector<world>(1 m, 0 m, 0 m); a vector of another dimension names it: vector<world, radiance>(…).
template <class S, class D>
std::ostream& operator<<(std::ostream& os, basic_vector<S, D> v) {
  const vec3_rep xyz = v.raw_value();
  std::string arguments(detail::space_label<S>());
  std::string unit;
  if constexpr (is_checked) {
    if constexpr (!std::is_same_v<D, dim::length>) (arguments += ", ") += dimension_name<D>();
    const std::string symbol = detail::unit_text(D{});
    if (!symbol.empty()) unit = " " + symbol;
  }
  detail::print_components(os, "vector", arguments, &xyz.x, 3, unit);
  return os;
}

template <class S>
std::ostream& operator<<(std::ostream& os, basic_direction<S> d) {
  const vec3_rep xyz = d.raw_value();
  detail::print_components(os, "direction", detail::space_label<S>(), &xyz.x, 3, "");
  return os;
}

template <class S>
std::ostream& operator<<(std::ostream& os, basic_normal<S> n) {
  const vec3_rep xyz = n.raw_value();
  detail::print_components(os, "normal", detail::space_label<S>(), &xyz.x, 3, "");
  return os;
}

template <class S>
std::ostream& operator<<(std::ostream& os, basic_hpoint<S> h) {
  const vec4_rep xyzw = h.raw_value();
  detail::print_components(os, "hpoint", detail::space_label<S>(), &xyzw.x, 4, "");
  return os;
}

template <class S>
std::ostream& operator<<(std::ostream& os, const basic_ray<S>& r) {
  return os << "ray(" << r.o << ", " << r.d << ')';
}

namespace detail {
template <class X>
struct printable_kind : std::false_type {};
template <class D, class T>
struct printable_kind<basic_quantity<D, T>> : std::true_type {};
template <class D>
struct printable_kind<basic_spectrum<D>> : std::true_type {};
template <class S>
struct printable_kind<basic_point<S>> : std::true_type {};
template <class S, class D>
struct printable_kind<basic_vector<S, D>> : std::true_type {};
template <class S>
struct printable_kind<basic_direction<S>> : std::true_type {};
template <class S>
struct printable_kind<basic_normal<S>> : std::true_type {};
template <class S>
struct printable_kind<basic_hpoint<S>> : std::true_type {};
template <class S>
struct printable_kind<basic_ray<S>> : std::true_type {};
}  // namespace detail

/// The typed kinds operator<< prints (plain numbers print as themselves).
template <class X>
concept printable = detail::printable_kind<X>::value;

/// What operator<< writes, as a string: to_string(2.0f * units::watt) is "2 W (power)".
template <printable X>
std::string to_string(const X& x) {
  std::ostringstream text;
  text << x;
  return std::move(text).str();
}

}  // namespace SAFEGI_MODE_NAMESPACE
}  // namespace safegi

#if defined(__cpp_lib_format)
/// std::format("{:.3g}", q): the spec formats the number; the unit and name follow.
template <class D, class T>
struct std::formatter<safegi::basic_quantity<D, T>, char> : std::formatter<T, char> {
  template <class Context>
  auto format(safegi::basic_quantity<D, T> q, Context& context) const {
    auto out = std::formatter<T, char>::format(q.raw_value(), context);
    const std::string suffix = safegi::SAFEGI_MODE_NAMESPACE::detail::unit_suffix<D>();
    return std::copy(suffix.begin(), suffix.end(), out);
  }
};
/// Spectra, points and the other kinds format as operator<< prints them (no spec).
template <class X>
  requires(safegi::printable<X> && !safegi::quantity_like<X>)
struct std::formatter<X, char> : std::formatter<std::string_view, char> {
  template <class Context>
  auto format(const X& x, Context& context) const {
    return std::formatter<std::string_view, char>::format(safegi::to_string(x), context);
  }
};
#endif
