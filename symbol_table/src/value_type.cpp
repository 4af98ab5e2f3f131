#include "safegi/symbol_table/value_type.hpp"

#include <array>
#include <utility>

namespace safegi::gl {
namespace {

constexpr std::array<std::pair<Kind, std::string_view>, 12> kKindNames{{
    {Kind::plain, "plain"},
    {Kind::scalar, "scalar"},
    {Kind::spectrum, "spectrum"},
    {Kind::point, "point"},
    {Kind::vector, "vector"},
    {Kind::direction, "direction"},
    {Kind::normal, "normal"},
    {Kind::hpoint, "hpoint"},
    {Kind::map, "map"},
    {Kind::projective_map, "projective_map"},
    {Kind::sampler, "sampler"},
    {Kind::block, "block"},
}};

std::string join_spaces(const std::vector<std::string>& spaces) {
  std::string joined;
  for (const auto& space : spaces) {
    if (!joined.empty()) joined += ", ";
    joined += space;
  }
  return joined.empty() ? "?" : joined;
}

}  // namespace

std::string_view to_string(Kind kind) {
  for (const auto& [k, name] : kKindNames)
    if (k == kind) return name;
  return "?";
}

std::optional<Kind> kind_from_string(std::string_view text) {
  for (const auto& [kind, name] : kKindNames)
    if (name == text) return kind;
  return std::nullopt;
}

void DimensionNamer::add(std::string name, DimensionExponents exponents) {
  derived_.emplace_back(std::move(name), std::move(exponents));
}

std::string DimensionNamer::name(const Dimension& dimension) const {
  if (!dimension.name.empty() && !dimension.name_is_hint) return dimension.name;
  if (dimension.exponents.empty()) return "1";
  for (const auto& [name, exponents] : derived_)
    if (exponents == dimension.exponents) return name;
  if (!dimension.name.empty()) return dimension.name;
  std::string product;
  for (const auto& [base, exponent] : dimension.exponents) {
    if (!product.empty()) product += '*';
    product += base;
    if (exponent != 1) product += '^' + std::to_string(exponent);
  }
  return product;
}

std::string in_words(const ValueType& type, const DimensionNamer& namer, const ValueType* texel) {
  switch (type.kind) {
    case Kind::plain:
    case Kind::block:
      return type.glsl_type;
    case Kind::scalar:
      if (type.dimension.exponents.empty()) return type.glsl_type;
      return type.glsl_type + '<' + namer.name(type.dimension) + '>';
    case Kind::spectrum:
      return "spectrum<" + namer.name(type.dimension) + '>';
    case Kind::vector:
      if (!type.dimension.exponents.empty() && type.dimension.exponents != DimensionExponents{{"length", 1}})
        return "vector<" + join_spaces(type.spaces) + ", " + namer.name(type.dimension) + '>';
      [[fallthrough]];
    case Kind::point:
    case Kind::direction:
    case Kind::normal:
    case Kind::hpoint:
    case Kind::map:
    case Kind::projective_map:
      return std::string(to_string(type.kind)) + '<' + join_spaces(type.spaces) + '>';
    case Kind::sampler:
      if (texel) return type.glsl_type + '<' + in_words(*texel, namer) + '>';
      return type.glsl_type;
  }
  return type.glsl_type;
}

namespace {

ValueType normalized(ValueType type) {
  if (type.kind == Kind::scalar && type.dimension.exponents.empty()) type.kind = Kind::plain;
  if (type.kind == Kind::vector && type.dimension.exponents.empty()) type.dimension.exponents = {{"length", 1}};
  return type;
}

}  // namespace

std::vector<std::string> differences(const ValueType& shader_type, const ValueType& host_type) {
  const ValueType shader = normalized(shader_type);
  const ValueType host = normalized(host_type);
  std::vector<std::string> parts;
  if (shader.kind != host.kind) parts.emplace_back("kind");
  if (shader.glsl_type != host.glsl_type) parts.emplace_back("GLSL type");
  if (shader.dimension != host.dimension) parts.emplace_back("dimension");
  if (shader.spaces != host.spaces) parts.emplace_back("space");
  return parts;
}

}  // namespace safegi::gl
