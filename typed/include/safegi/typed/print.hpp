// Printing typed values: the number in its reference unit, the unit, and the dimension
// in words, so a log line says what it holds:
//   std::cout << L;                 // 2 W·m⁻²·sr⁻¹ (radiance)
//   safegi::to_string(p)            // point<world>(1 m, 2 m, 0 m)
// The unit is built from the reference units of the base dimensions (m, s, J, rad, sr;
// energy per time is W); proj has no unit, so it shows only in the dimension's name.
// A user base dimension is shown by its name. The unchecked build has no dimensions or
// spaces left to print: there a quantity is a float and a point prints as point(1, 2, 0).
//
// std::format support is in format.hpp (not included by typed.hpp).
#pragma once

#include <cstdio>
#include <iosfwd>
#include <string_view>

#include "safegi/typed/ray.hpp"
#include "safegi/typed/space.hpp"
#include "safegi/typed/spectrum.hpp"

// Printing costs a file that does not print nothing: only <iosfwd> is included. The
// unit text is computed at compile time; operator<< is a template over the stream, so
// it needs <ostream> only where it is used (which std::cout or a std::ostringstream
// brings anyway), and to_string needs <string>.

// The unit text, the same in every mode (computed at compile time).
namespace safegi::text_detail {
/// The symbol of a base dimension's reference unit; proj has none.
constexpr std::string_view reference_unit_symbol(std::string_view base) {
  if (base == "length") return "m";
  if (base == "time") return "s";
  if (base == "energy") return "J";
  if (base == "angle") return "rad";
  if (base == "solid_angle") return "sr";
  if (base == "proj") return "";
  return base;  // a user base dimension: its own name
}

constexpr void append_superscript(text_buffer& text, int exponent) {
  constexpr std::string_view digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  if (exponent == 1) return;
  if (exponent < 0) text += "⁻";
  long long magnitude = exponent < 0 ? -static_cast<long long>(exponent) : exponent;
  long long place = 1;
  while (place * 10 <= magnitude) place *= 10;
  for (; place > 0; place /= 10) text += digits[(magnitude / place) % 10];
}

constexpr void append_unit_power(text_buffer& text, std::string_view symbol, int exponent) {
  if (symbol.empty() || exponent == 0) return;
  if (!text.empty()) text += "·";
  text += symbol;
  append_superscript(text, exponent);
}

/// Energy and time with opposite exponents print as watts (W·m⁻² rather than J·m⁻²·s⁻¹).
template <class... Terms>
constexpr text_buffer unit_text(dimension<Terms...>) {
  int energy = 0, time = 0;
  ((Terms::base::name.view() == "energy" ? energy = Terms::exponent : 0), ...);
  ((Terms::base::name.view() == "time" ? time = Terms::exponent : 0), ...);
  const int watts = energy != 0 && energy == -time ? energy : 0;
  text_buffer text;
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
template <class D>
constexpr text_buffer unit_suffix() {
  const text_buffer unit = unit_text(D{});
  text_buffer suffix;
  if (!unit.empty()) (suffix += " ") += unit.view();
  if (!std::is_same_v<D, dim::dimensionless>) ((suffix += " (") += dimension_name<D>()) += ")";
  return suffix;
}
/// " m" for a length: the unit alone, as each component of a vector shows it.
template <class D>
constexpr text_buffer component_unit() {
  const text_buffer unit = unit_text(D{});
  text_buffer text;
  if (!unit.empty()) (text += " ") += unit.view();
  return text;
}
/// "world" or "world, radiance": a vector's arguments (its dimension unless a length).
template <class S, class D>
constexpr text_buffer vector_arguments() {
  text_buffer text;
  text += S::name.view();
  if (!std::is_same_v<D, dim::length>) (text += ", ") += dimension_name<D>();
  return text;
}

template <class D>
inline constexpr auto frozen_unit_suffix = freeze([] { return unit_suffix<D>(); });
template <class D>
inline constexpr auto frozen_component_unit = freeze([] { return component_unit<D>(); });
template <class S, class D>
inline constexpr auto frozen_vector_arguments = freeze([] { return vector_arguments<S, D>(); });
}  // namespace safegi::text_detail

namespace safegi {
inline namespace SAFEGI_MODE_NAMESPACE {
namespace detail {

template <class D>
constexpr std::string_view suffix_of() {
  if constexpr (is_checked) return text_detail::frozen_unit_suffix<D>.view();
  return {};
}
template <class S>
constexpr std::string_view space_label() {
  if constexpr (is_checked) return S::name.view();
  return {};
}

/// Where printed text goes: a stream (the number as the stream's flags format it), or a
/// string (the number as a default-formatted stream would write it, %g).
template <class Stream>
struct stream_sink {
  Stream& out;
  void text(std::string_view piece) { out << piece; }
  template <class T>
  void number(T value) {
    out << value;
  }
};
template <class String>
struct string_sink {
  String& out;
  void text(std::string_view piece) { out.append(piece.data(), piece.size()); }
  void number(double value) {
    char digits[32];
    const int length = std::snprintf(digits, sizeof digits, "%g", value);
    out.append(digits, static_cast<std::size_t>(length));
  }
};

/// kind<arguments>(a, b, c): each component followed by `unit` (" m" for a point).
template <class Sink, class T>
void print_components(Sink sink, std::string_view kind, std::string_view arguments, const T* xyz, int count,
                      std::string_view unit) {
  sink.text(kind);
  if (!arguments.empty()) {
    sink.text("<");
    sink.text(arguments);
    sink.text(">");
  }
  sink.text("(");
  for (int i = 0; i < count; ++i) {
    if (i) sink.text(", ");
    sink.number(xyz[i]);
    sink.text(unit);
  }
  sink.text(")");
}

template <class Sink, class D, class T>
void print(Sink sink, basic_quantity<D, T> q) {
  sink.number(q.raw_value());
  sink.text(suffix_of<D>());
}
template <class Sink, class D>
void print(Sink sink, basic_spectrum<D> s) {
  const vec3_rep rgb = s.raw_value();
  print_components(sink, "", "", &rgb.r, 3, "");
  sink.text(suffix_of<D>());
}
template <class Sink, class S>
void print(Sink sink, basic_point<S> p) {
  const vec3_rep xyz = p.raw_value();
  print_components(sink, "point", space_label<S>(), &xyz.x, 3, is_checked ? " m" : "");
}
/// vector<world>(1 m, 0 m, 0 m); a vector of another dimension names it: vector<world, radiance>(…).
template <class Sink, class S, class D>
void print(Sink sink, basic_vector<S, D> v) {
  const vec3_rep xyz = v.raw_value();
  if constexpr (is_checked)
    print_components(sink, "vector", text_detail::frozen_vector_arguments<S, D>.view(), &xyz.x, 3,
                     text_detail::frozen_component_unit<D>.view());
  else
    print_components(sink, "vector", "", &xyz.x, 3, "");
}
template <class Sink, class S>
void print(Sink sink, basic_direction<S> d) {
  const vec3_rep xyz = d.raw_value();
  print_components(sink, "direction", space_label<S>(), &xyz.x, 3, "");
}
template <class Sink, class S>
void print(Sink sink, basic_normal<S> n) {
  const vec3_rep xyz = n.raw_value();
  print_components(sink, "normal", space_label<S>(), &xyz.x, 3, "");
}
template <class Sink, class S>
void print(Sink sink, basic_hpoint<S> h) {
  const vec4_rep xyzw = h.raw_value();
  print_components(sink, "hpoint", space_label<S>(), &xyzw.x, 4, "");
}
template <class Sink, class S>
void print(Sink sink, const basic_ray<S>& r) {
  sink.text("ray(");
  print(sink, r.o);
  sink.text(", ");
  print(sink, r.d);
  sink.text(")");
}
}  // namespace detail

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

/// std::cout << L: the number as the stream's flags format it, its unit and dimension.
template <class Traits, printable X>
std::basic_ostream<char, Traits>& operator<<(std::basic_ostream<char, Traits>& os, const X& x) {
  detail::print(detail::stream_sink<std::basic_ostream<char, Traits>>{os}, x);
  return os;
}

/// What operator<< writes to a default-formatted stream, as a string: to_string(2.0f *
/// units::watt) is "2 W (power)". (The second parameter only defers std::string to the
/// call, so that a file which never calls it need not include <string>.)
template <printable X, class String = std::string>
String to_string(const X& x) {
  String text;
  detail::print(detail::string_sink<String>{text}, x);
  return text;
}

}  // namespace SAFEGI_MODE_NAMESPACE
}  // namespace safegi
