// A string usable as a template argument: base dimensions and spaces are named with one,
// for printing and reflection. (Compile errors name them by type instead, diagnose.hpp:
// clang 14 prints a fixed_string argument as character codes.)
#pragma once

#include <cstddef>
#include <string_view>

namespace safegi {

template <std::size_t N>
struct fixed_string {
  char text[N]{};  // the only member, so g++ prints the value as {"text"}

  constexpr fixed_string() = default;
  constexpr fixed_string(const char (&literal)[N]) {  // NOLINT: implicit on purpose
    for (std::size_t i = 0; i < N; ++i) text[i] = literal[i];
  }

  [[nodiscard]] constexpr std::size_t size() const { return N - 1; }
  [[nodiscard]] constexpr std::string_view view() const { return {text, N - 1}; }
};

template <std::size_t N>
fixed_string(const char (&)[N]) -> fixed_string<N>;

template <std::size_t N, std::size_t M>
constexpr bool operator==(const fixed_string<N>& a, const fixed_string<M>& b) {
  return a.view() == b.view();
}

// Compile-time text, in a namespace of its own so that headers whose own detail is
// inside the mode's inline namespace can name it (safegi::detail would be ambiguous).
namespace text_detail {
/// A small constexpr string builder (g++ 12's constexpr std::string trips over its
/// small-string buffer, so compile-time text is built here instead).
struct text_buffer {
  static constexpr std::size_t capacity = 512;
  char chars[capacity]{};
  std::size_t length = 0;

  constexpr text_buffer& operator+=(std::string_view piece) {
    for (char c : piece)
      if (length + 1 < capacity) chars[length++] = c;
    return *this;
  }
  constexpr text_buffer& operator+=(int value) {
    char digits[16]{};
    int count = 0;
    long magnitude = value < 0 ? -static_cast<long>(value) : value;
    do {
      digits[count++] = static_cast<char>('0' + magnitude % 10);
      magnitude /= 10;
    } while (magnitude > 0);
    if (value < 0) *this += "-";
    while (count > 0) *this += std::string_view(&digits[--count], 1);
    return *this;
  }
  [[nodiscard]] constexpr std::string_view view() const { return {chars, length}; }
  [[nodiscard]] constexpr bool empty() const { return length == 0; }
};

/// Freezes the text of a constexpr text_buffer producer into a fixed_string.
template <class Producer>
constexpr auto freeze(Producer produce) {
  constexpr std::size_t length = Producer{}().length;
  fixed_string<length + 1> out{};
  const text_buffer text = produce();
  for (std::size_t i = 0; i < length; ++i) out.text[i] = text.chars[i];
  return out;
}
}  // namespace text_detail

namespace detail {
using text_detail::freeze;
using text_detail::text_buffer;
}  // namespace detail

}  // namespace safegi
