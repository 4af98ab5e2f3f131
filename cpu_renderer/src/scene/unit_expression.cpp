#include "safegi/cpu_renderer/unit_expression.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <utility>
#include <vector>

namespace safegi::render {

const DimensionRegistry& scene_vocabulary() {
  static const DimensionRegistry vocabulary = DimensionRegistry::rendering_prelude();
  return vocabulary;
}

namespace {

BaseId base_id(std::string_view name) { return *scene_vocabulary().find_base(name); }

RuntimeDimension without_proj(const RuntimeDimension& dimension) {
  std::vector<Factor> factors;
  for (const Factor& f : dimension.factors())
    if (f.base != base_id("proj")) factors.push_back(f);
  return *RuntimeDimension::from_factors(std::move(factors));
}

}  // namespace

RuntimeDimension runtime_dim::make(int length, int time, int energy, int angle, int solid_angle) {
  return *RuntimeDimension::from_factors({{base_id("length"), length},
                                          {base_id("time"), time},
                                          {base_id("energy"), energy},
                                          {base_id("angle"), angle},
                                          {base_id("solid_angle"), solid_angle}});
}

RuntimeDimension runtime_dim::named(std::string_view vocabulary_name) {
  return without_proj(*scene_vocabulary().find_dimension(vocabulary_name));
}

RuntimeDimension runtime_dim::with_base_power(const RuntimeDimension& dimension, std::string_view base, int exponent) {
  const std::optional<BaseId> id = scene_vocabulary().find_base(base);
  if (!id || *id == base_id("proj")) return dimension;
  return *multiply(dimension, RuntimeDimension::base(*id, exponent));
}

namespace {

// The vocabulary's dimensions a scene message names, with an example of the unit a scene
// file writes for each; any other dimension is spelled in base symbols ("m s^-1").
struct NamedDimension {
  std::string_view vocabulary_name;
  const char* example;
};

const NamedDimension kNamedDimensions[] = {
    {"dimensionless", "0.5"}, {"length", "m"},     {"area", "m2"},          {"time", "s"},
    {"energy", "J"},          {"angle", "deg"},    {"solid_angle", "sr"},   {"power", "W"},
    {"intensity", "W/sr"},    {"irradiance", "W/m2"}, {"radiance", "W/(m2 sr)"},
};

// "solid angle"; the dimensionless one is a "dimensionless number".
std::string display_name(std::string_view vocabulary_name) {
  if (vocabulary_name == "dimensionless") return "dimensionless number";
  std::string text(vocabulary_name);
  for (char& c : text)
    if (c == '_') c = ' ';
  return text;
}

const NamedDimension* find_named(const RuntimeDimension& dimension) {
  for (const NamedDimension& named : kNamedDimensions)
    if (runtime_dim::named(named.vocabulary_name) == dimension) return &named;
  return nullptr;
}

// What a scene file may write for a unit: its symbol (vocabulary.def), or its name or alias.
struct UnitSymbol {
  std::string_view symbol;
  std::string_view unit;
};

constexpr UnitSymbol kUnitSymbols[] = {
#define VOCABULARY_UNIT(name, symbol, dimension, scale) {symbol, #name},
#include "safegi/typed/vocabulary.def"
};

const ::safegi::Unit* find_scene_unit(std::string_view text) {
  for (const UnitSymbol& candidate : kUnitSymbols)
    if (!candidate.symbol.empty() && candidate.symbol == text) return scene_vocabulary().find_unit(candidate.unit);
  return scene_vocabulary().find_unit(text);
}

// A base's symbol: that of the vocabulary's unit of scale 1 that measures it (m, s, J, rad, sr).
std::string_view base_symbol(BaseId base) {
  for (const UnitSymbol& candidate : kUnitSymbols) {
    const ::safegi::Unit* unit = scene_vocabulary().find_unit(candidate.unit);
    if (!candidate.symbol.empty() && unit->scale == 1.0 && unit->dimension == RuntimeDimension::base(base))
      return candidate.symbol;
  }
  return scene_vocabulary().base_name(base);
}

std::string base_spelling(const RuntimeDimension& dimension) {
  std::string text;
  for (const Factor& f : dimension.factors()) {
    if (!text.empty()) text += ' ';
    text += base_symbol(f.base);
    if (f.exponent != 1) text += '^' + std::to_string(f.exponent);
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
      while (!at_end() && (std::isalpha(static_cast<unsigned char>(peek())) || peek() == '_')) ++pos_;
      std::string_view symbol = text_.substr(start, pos_ - start);
      if (symbol.empty()) return fail(error, "expected a unit symbol at '" + std::string(text_.substr(start)) + "'");
      const ::safegi::Unit* found = find_scene_unit(symbol);
      if (!found) return fail(error, "unknown unit '" + std::string(symbol) + "'");
      factor = Unit{found->scale, without_proj(found->dimension)};
    }
    int exponent = 1;
    if (!parse_exponent(exponent, error)) return false;
    unit.to_reference *= std::pow(factor.to_reference, sign * exponent);
    Checked<RuntimeDimension> raised = power(factor.dimension, sign * exponent);
    Checked<RuntimeDimension> product = raised ? multiply(unit.dimension, *raised) : raised;
    if (!product) return fail(error, "exponent out of range");
    unit.dimension = *product;
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
  if (const NamedDimension* named = find_named(dimension)) return display_name(named->vocabulary_name);
  return base_spelling(dimension);
}

std::string describe(const RuntimeDimension& dimension) {
  if (const NamedDimension* named = find_named(dimension))
    return display_name(named->vocabulary_name) + " (e.g. " + named->example + ")";
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
