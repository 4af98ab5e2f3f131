#pragma once
// Hover and go to definition, from the checker's symbols
// (CheckOptions::record_symbols) of the document's last analysis.

#include <string>

#include <safegi/typechecker/type.hpp>

#include "analysis.hpp"

namespace safegi::lsp {

// A type with its dimension in physical words and its spaces:
// `spectrum<radiance> — W·m⁻²·sr⁻¹`, `point<world> — m, in space world`,
// `map<object, world> — from space object to space world`.
std::string physical_words(const Type& type, const std::string& type_text, const DimensionRegistry& registry);
// The dimension as a product of base dimensions, when that says more than its
// name (`radiance = energy·length⁻²·time⁻¹·solid_angle⁻¹·proj⁻¹`), and why
// proj is not among the SI words; empty otherwise.
std::string dimension_equation(const DimSlot& dim, const DimensionRegistry& registry);

struct HoverStyle {
  bool markdown = true;  // else plain text
};

// The Hover result at `offset` of the document, or null.
json hover(const Analysis& analysis, const Locator& locator, std::size_t offset, HoverStyle style);
// The Location of the declaration of the name at `offset` (or of the file an
// #include there names), or null.
json definition(const Analysis& analysis, const Locator& locator, std::size_t offset);

}  // namespace safegi::lsp
