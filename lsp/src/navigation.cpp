#include "navigation.hpp"

#include <algorithm>
#include <string_view>
#include <vector>

#include <safegi/diagnostics/codes.hpp>

#include <safegi/typechecker/checker.hpp>

#include "uri.hpp"

namespace safegi::lsp {
namespace {

// The innermost name at `offset`: one that contains it, else one that ends
// there (the cursor just after a word).
const SymbolOccurrence* symbol_at(const StageAnalysis& stage, const Locator& locator, std::size_t offset) {
  const SymbolOccurrence* best = nullptr;
  bool best_inside = false;
  for (const SymbolOccurrence& o : stage.checked.symbols) {
    if (!o.range.valid() || !locator.in_document(o.range.begin.file)) continue;
    const std::size_t begin = o.range.begin.offset, end = o.range.end.offset;
    if (offset < begin || offset > end) continue;
    const bool inside = offset < end;
    if (best && (best_inside && !inside)) continue;
    if (best && best_inside == inside && best->range.length() <= o.range.length()) continue;
    best = &o;
    best_inside = inside;
  }
  return best;
}

std::string space_name(const SpaceSlot& s, const DimensionRegistry& registry) {
  return s.is_known() ? registry.space_name(s.id) : "?";
}

}  // namespace

std::string physical_words(const Type& type, const std::string& type_text, const DimensionRegistry& registry) {
  if (type.is_error()) return {};
  if (type.texel) {
    const std::string texel = type_name(*type.texel, registry);
    const std::string words = physical_words(*type.texel, texel, registry);
    return type_text + " — texels " + (words.empty() ? texel : words);
  }
  std::string units;
  switch (type.dim.state) {
    case DimSlot::State::known: units = registry.format_si(type.dim.value); break;
    case DimSlot::State::generic: units = "any dimension (a template parameter)"; break;
    case DimSlot::State::zero: units = "0 (fits any dimension)"; break;
    case DimSlot::State::unknown: break;
  }
  const std::string space = "space " + space_name(type.from, registry);
  std::string words;
  switch (type.geometry) {
    case Geometry::none:
    case Geometry::spectrum: words = units.empty() ? "unannotated (plain GLSL)" : units; break;
    case Geometry::point:
    case Geometry::vector: words = units + ", in " + space; break;
    case Geometry::direction: words = "unit vector in " + space; break;
    case Geometry::normal: words = "unit normal in " + space; break;
    case Geometry::hpoint: words = "homogeneous point in " + space; break;
    case Geometry::map:
    case Geometry::rigidmap:
    case Geometry::projmap:
      words = std::string(type.geometry == Geometry::rigidmap ? "rigid map" : type.geometry == Geometry::projmap ? "projective map" : "map") +
              " from " + space + " to space " + space_name(type.to, registry);
      break;
  }
  if (type.dim.is_known() && type.dim.value.is_dimensionless() && type.geometry == Geometry::none) words += " (dimensionless)";
  return type_text + " — " + words;
}

std::string dimension_equation(const DimSlot& dim, const DimensionRegistry& registry) {
  if (!dim.is_known() || dim.value.is_dimensionless()) return {};
  const std::string name = dim_name(dim, registry), product = registry.format_product(dim.value);
  std::string out = name == product ? "" : name + " = " + product;
  const std::optional<BaseId> proj = registry.find_base("proj");
  if (proj && dim.value.exponent(*proj) != 0)
    out += std::string(out.empty() ? "" : "; ") + "the SI units leave out proj, the projected-cosine factor (a pure number in SI)";
  return out;
}

namespace {

// What a name is: its declaration as code, its physical meaning in words, its dimension's equation.
std::string symbol_hover_text(const SymbolOccurrence* o, const DimensionRegistry& registry, HoverStyle style) {
  std::string code, words, equation;
  switch (o->kind) {
    case SymbolKind::variable:
    case SymbolKind::field:
    case SymbolKind::builtin_variable:
      code = o->type_text + " " + o->name;
      words = physical_words(o->type, o->type_text, registry);
      equation = dimension_equation(o->type.dim, registry);
      if (o->kind == SymbolKind::builtin_variable) words += words.empty() ? "built-in variable" : " (built-in variable)";
      break;
    case SymbolKind::function:
    case SymbolKind::builtin_function: {
      code = o->type_text.empty() ? o->name : o->type_text;
      const std::string result = type_name(o->type, registry);
      if (!o->type.is_error() && o->type.shape != Shape::void_)
        words = (o->is_declaration ? "returns " : "here returns ") + physical_words(o->type, result, registry);
      if (o->kind == SymbolKind::builtin_function) words = "built-in function" + (words.empty() ? "" : "; " + words);
      break;
    }
    case SymbolKind::structure: code = o->type_text; break;
    case SymbolKind::dimension: {
      const bool base = registry.find_base(o->name).has_value();
      code = "dimension " + o->name;
      if (!o->type.is_error()) {
        words = o->name + " — " + registry.format_si(o->type.dim.value) + (base ? " (a base dimension)" : "");
        equation = dimension_equation(o->type.dim, registry);
      }
      break;
    }
    case SymbolKind::unit: {
      const Unit* unit = registry.find_unit(o->name);
      code = "unit " + o->name;
      if (unit) {
        const std::string scale = DimensionRegistry::format_number(unit->scale);  // as the checker prints numbers
        code += " : " + registry.format(unit->dimension) + " = " + scale;
        words = "1 " + o->name + " = " + scale + " " + registry.format_si(unit->dimension);
      }
      break;
    }
    case SymbolKind::space: code = "space " + o->name; break;
    case SymbolKind::dimension_parameter: code = "dimension " + o->name; words = "template parameter"; break;
    case SymbolKind::space_parameter: code = "space " + o->name; words = "template parameter"; break;
  }
  std::string value;
  if (style.markdown) {
    value = "```glsl\n" + code + "\n```";
    if (!words.empty()) value += "\n" + words;
    if (!equation.empty()) value += "\n\n" + equation;
  } else {
    value = code;
    if (!words.empty()) value += "\n" + words;
    if (!equation.empty()) value += "\n" + equation;
  }
  return value;
}

// `safeglslc --explain` of every diagnostic code reported where the cursor is, once each.
std::string explanations_at(const Analysis& analysis, const Locator& locator, std::size_t offset, SourceRange& range) {
  std::string text;
  std::vector<std::string_view> seen;
  for (const Diagnostic& d : analysis.result.diagnostics) {
    const SourceRange shown = locator.in_document_range(d.range);
    if (d.code.empty() || !shown.valid() || !locator.in_document(shown.begin.file)) continue;
    if (offset < shown.begin.offset || offset > shown.end.offset) continue;
    if (std::find(seen.begin(), seen.end(), d.code) != seen.end()) continue;
    seen.push_back(d.code);
    std::string explanation = explain_diagnostic_code(d.code);
    if (explanation.empty()) continue;
    while (!explanation.empty() && explanation.back() == '\n') explanation.pop_back();
    text += (text.empty() ? "" : "\n\n") + explanation;
    if (!range.valid()) range = shown;
  }
  return text;
}

}  // namespace

json hover(const Analysis& analysis, const Locator& locator, std::size_t offset, HoverStyle style) {
  const StageAnalysis* stage = analysis.stage();
  const SymbolOccurrence* o = stage ? symbol_at(*stage, locator, offset) : nullptr;
  std::string value = o ? symbol_hover_text(o, stage->checked.registry, style) : "";
  SourceRange range = o ? o->range : SourceRange{};
  const std::string explanations = explanations_at(analysis, locator, offset, range);
  if (!explanations.empty()) value += (value.empty() ? "" : style.markdown ? "\n\n---\n\n" : "\n\n") + explanations;
  if (value.empty()) return nullptr;
  return {{"contents", {{"kind", style.markdown ? "markdown" : "plaintext"}, {"value", value}}},
          {"range", locator.range(range)}};
}

json definition(const Analysis& analysis, const Locator& locator, std::size_t offset) {
  const StageAnalysis* stage = analysis.stage();
  if (!stage) return nullptr;
  if (const SymbolOccurrence* o = symbol_at(*stage, locator, offset)) {
    if (std::optional<json> where = locator.location(o->declaration)) return *where;
    return nullptr;
  }
  // On an #include line: the file it names.
  for (const IncludedFile& inc : stage->preprocessed.includes) {
    if (!locator.in_document(inc.directive.begin.file)) continue;
    if (offset < inc.directive.begin.offset || offset > inc.directive.end.offset) continue;
    if (std::optional<std::string> uri = locator.uri(inc.file)) return {{"uri", *uri}, {"range", range_json({}, {})}};
  }
  return nullptr;
}

}  // namespace safegi::lsp
