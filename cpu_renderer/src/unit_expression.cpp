#include "safegi/cpu_renderer/unit_expression.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <utility>

namespace safegi::render {

RuntimeDimension RuntimeDimension::operator*(const RuntimeDimension& other) const {
  RuntimeDimension result;
  for (size_t i = 0; i < exponents.size(); ++i) result.exponents[i] = exponents[i] + other.exponents[i];
  return result;
}

RuntimeDimension RuntimeDimension::inverse() const { return pow(-1); }

RuntimeDimension RuntimeDimension::pow(int power) const {
  RuntimeDimension result;
  for (size_t i = 0; i < exponents.size(); ++i) result.exponents[i] = exponents[i] * power;
  return result;
}

RuntimeDimension runtime_dim::make(int length, int time, int energy, int angle, int solid_angle) {
  return RuntimeDimension{{length, time, energy, angle, solid_angle}};
}

namespace {

struct NamedDimension {
  RuntimeDimension dimension;
  const char* name;
  const char* example;
};

const NamedDimension kNamedDimensions[] = {
    {runtime_dim::none, "dimensionless number", "0.5"},
    {runtime_dim::length, "length", "m"},
    {runtime_dim::make(2, 0, 0, 0, 0), "area", "m2"},
    {runtime_dim::time, "time", "s"},
    {runtime_dim::make(0, 0, 1, 0, 0), "energy", "J"},
    {runtime_dim::angle, "angle", "deg"},
    {runtime_dim::make(0, 0, 0, 0, 1), "solid angle", "sr"},
    {runtime_dim::power, "power", "W"},
    {runtime_dim::intensity, "intensity", "W/sr"},
    {runtime_dim::make(-2, -1, 1, 0, 0), "irradiance", "W/m2"},
    {runtime_dim::radiance, "radiance", "W/(m2 sr)"},
};

struct UnitSymbol {
  std::string_view symbol;
  double to_reference;
  RuntimeDimension dimension;
};

const UnitSymbol kUnitSymbols[] = {
    {"m", 1.0, runtime_dim::length},
    {"km", 1e3, runtime_dim::length},
    {"cm", 1e-2, runtime_dim::length},
    {"mm", 1e-3, runtime_dim::length},
    {"um", 1e-6, runtime_dim::length},
    {"nm", 1e-9, runtime_dim::length},
    {"in", 0.0254, runtime_dim::length},
    {"ft", 0.3048, runtime_dim::length},
    {"s", 1.0, runtime_dim::time},
    {"ms", 1e-3, runtime_dim::time},
    {"us", 1e-6, runtime_dim::time},
    {"ns", 1e-9, runtime_dim::time},
    {"J", 1.0, runtime_dim::make(0, 0, 1, 0, 0)},
    {"kJ", 1e3, runtime_dim::make(0, 0, 1, 0, 0)},
    {"W", 1.0, runtime_dim::power},
    {"mW", 1e-3, runtime_dim::power},
    {"kW", 1e3, runtime_dim::power},
    {"rad", 1.0, runtime_dim::angle},
    {"deg", std::numbers::pi / 180.0, runtime_dim::angle},
    {"sr", 1.0, runtime_dim::make(0, 0, 0, 0, 1)},
};

std::string base_spelling(const RuntimeDimension& dimension) {
  static const char* const kBaseSymbols[] = {"m", "s", "J", "rad", "sr"};
  std::string text;
  for (size_t i = 0; i < dimension.exponents.size(); ++i) {
    int exponent = dimension.exponents[i];
    if (exponent == 0) continue;
    if (!text.empty()) text += ' ';
    text += kBaseSymbols[i];
    if (exponent != 1) text += '^' + std::to_string(exponent);
  }
  return text;
}

// Recursive-descent parser over a unit expression.
class UnitParser {
 public:
  explicit UnitParser(std::string_view text) : text_(text) {}

  std::optional<Unit> parse_all(std::string& error) {
    skip_space();
    Unit unit;
    if (at_end()) return unit;
    if (!parse_product(unit, error)) return std::nullopt;
    skip_space();
    if (!at_end()) {
      fail(error, "unexpected '" + std::string(1, peek()) + "'");
      return std::nullopt;
    }
    return unit;
  }

 private:
  bool at_end() const { return pos_ >= text_.size(); }
  char peek() const { return text_[pos_]; }
  void skip_space() {
    while (!at_end() && peek() == ' ') ++pos_;
  }
  bool skip_middle_dot() {  // UTF-8 '·'
    if (text_.substr(pos_, 2) == "\xC2\xB7") {
      pos_ += 2;
      return true;
    }
    return false;
  }
  static bool fail(std::string& error, std::string message) {
    error = std::move(message);
    return false;
  }

  // product := factor (('*' | '·' | ' ' | '/') factor)*
  bool parse_product(Unit& unit, std::string& error) {
    if (!parse_factor(unit, +1, error)) return false;
    for (;;) {
      skip_space();
      if (at_end() || peek() == ')') return true;
      int sign = +1;
      if (peek() == '/') {
        sign = -1;
        ++pos_;
      } else if (peek() == '*') {
        ++pos_;
      } else {
        skip_middle_dot();
      }
      skip_space();
      if (!parse_factor(unit, sign, error)) return false;
    }
  }

  // factor := (symbol | '(' product ')') [['^'] integer]
  bool parse_factor(Unit& unit, int sign, std::string& error) {
    if (at_end()) return fail(error, "missing unit after operator");
    Unit factor;
    if (peek() == '(') {
      ++pos_;
      skip_space();
      if (!parse_product(factor, error)) return false;
      if (at_end() || peek() != ')') return fail(error, "missing ')'");
      ++pos_;
    } else {
      size_t start = pos_;
      while (!at_end() && std::isalpha(static_cast<unsigned char>(peek()))) ++pos_;
      std::string_view symbol = text_.substr(start, pos_ - start);
      if (symbol.empty()) return fail(error, "expected a unit symbol at '" + std::string(text_.substr(start)) + "'");
      const UnitSymbol* found = nullptr;
      for (const UnitSymbol& candidate : kUnitSymbols)
        if (candidate.symbol == symbol) found = &candidate;
      if (!found) return fail(error, "unknown unit '" + std::string(symbol) + "'");
      factor = Unit{found->to_reference, found->dimension};
    }
    int exponent = 1;
    if (!parse_exponent(exponent, error)) return false;
    unit.to_reference *= std::pow(factor.to_reference, sign * exponent);
    unit.dimension = unit.dimension * factor.dimension.pow(sign * exponent);
    return true;
  }

  bool parse_exponent(int& exponent, std::string& error) {
    bool caret = !at_end() && peek() == '^';
    if (caret) ++pos_;
    size_t start = pos_;
    if (!at_end() && (peek() == '-' || peek() == '+')) ++pos_;
    while (!at_end() && std::isdigit(static_cast<unsigned char>(peek()))) ++pos_;
    if (pos_ == start || (pos_ == start + 1 && !std::isdigit(static_cast<unsigned char>(text_[start])))) {
      pos_ = start;
      if (caret) return fail(error, "missing exponent after '^'");
      return true;
    }
    std::string_view digits = text_.substr(start, pos_ - start);
    if (digits.front() == '+') digits.remove_prefix(1);
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), exponent);
    if (ec != std::errc() || end != digits.data() + digits.size() || exponent < -8 || exponent > 8)
      return fail(error, "exponent out of range");
    return true;
  }

  std::string_view text_;
  size_t pos_ = 0;
};

}  // namespace

std::string dimension_name(const RuntimeDimension& dimension) {
  for (const NamedDimension& named : kNamedDimensions)
    if (named.dimension == dimension) return named.name;
  return base_spelling(dimension);
}

std::string describe(const RuntimeDimension& dimension) {
  for (const NamedDimension& named : kNamedDimensions)
    if (named.dimension == dimension) return std::string(named.name) + " (e.g. " + named.example + ")";
  return base_spelling(dimension);
}

std::optional<Unit> parse_unit(std::string_view text, std::string& error) {
  return UnitParser(text).parse_all(error);
}

std::optional<Quantity> parse_quantity(std::string_view text, std::string& error) {
  size_t start = 0;
  while (start < text.size() && text[start] == ' ') ++start;
  // from_chars does not accept a leading '+'.
  if (start < text.size() && text[start] == '+') ++start;
  double number = 0.0;
  auto [end, ec] = std::from_chars(text.data() + start, text.data() + text.size(), number);
  if (ec != std::errc() || !std::isfinite(number)) {
    error = "expected a number followed by a unit";
    return std::nullopt;
  }
  std::optional<Unit> unit = parse_unit(std::string_view(end, text.data() + text.size() - end), error);
  if (!unit) return std::nullopt;
  return Quantity{number * unit->to_reference, unit->dimension};
}

}  // namespace safegi::render
