// std::format for typed values, where the standard library has <format>
// (__cpp_lib_format; not libstdc++ 12): the spec formats the number of a quantity and
// the same unit and dimension name as operator<< follow,
//   std::format("{:.2f}", L)   // "2.00 W·m⁻²·sr⁻¹ (radiance)"
// and the other kinds format as they print. Not included by typed.hpp: <format> alone
// costs more to compile than the whole library.
#pragma once

#include <string>
#include <string_view>

#include "safegi/typed/print.hpp"

#if defined(__has_include)
#if __has_include(<version>)
#include <version>
#endif
#endif
#if defined(__cpp_lib_format)
#include <algorithm>
#include <format>

/// std::format("{:.3g}", q): the spec formats the number; the unit and name follow.
template <class D, class T>
struct std::formatter<safegi::basic_quantity<D, T>, char> : std::formatter<T, char> {
  template <class Context>
  auto format(safegi::basic_quantity<D, T> q, Context& context) const {
    auto out = std::formatter<T, char>::format(q.raw_value(), context);
    const std::string_view suffix = safegi::SAFEGI_MODE_NAMESPACE::detail::suffix_of<D>();
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
