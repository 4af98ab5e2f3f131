#include "completion.hpp"

#include <algorithm>
#include <optional>
#include <set>

#include <safegi/lexer/preprocessor.hpp>

namespace safegi::lsp {
namespace {

bool word_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// The word that ends at `end` (after skipping spaces backwards), and where it starts.
std::string_view word_before(std::string_view text, std::size_t& end) {
  while (end > 0 && (text[end - 1] == ' ' || text[end - 1] == '\t' || text[end - 1] == '\n' || text[end - 1] == '\r')) --end;
  std::size_t begin = end;
  while (begin > 0 && word_char(text[begin - 1])) --begin;
  std::string_view word = text.substr(begin, end - begin);
  end = begin;
  return word;
}

// What the type word before an annotation's `<` expects as its argument `index`.
Expected annotation_argument(std::string_view word, int index) {
  static constexpr std::string_view kDimensioned[] = {"float", "double", "vec2", "vec3", "vec4",
                                                      "dvec2", "dvec3", "dvec4", "spectrum"};
  static constexpr std::string_view kSpaced[] = {"point", "direction", "normal", "hpoint", "map", "rigidmap", "projmap"};
  if (std::find(std::begin(kDimensioned), std::end(kDimensioned), word) != std::end(kDimensioned)) return Expected::dimension;
  if ((word == "point" || word == "direction") && index == 1) return Expected::orientation;
  if (std::find(std::begin(kSpaced), std::end(kSpaced), word) != std::end(kSpaced)) return Expected::space;
  if (word == "vector") return index == 0 ? Expected::space : index == 1 ? Expected::dimension : Expected::orientation;
  if (word == "template") return Expected::template_parameter_kind;
  for (std::string_view sampler : {"sampler", "isampler", "usampler", "texture", "itexture", "utexture"})
    if (word.substr(0, sampler.size()) == sampler && word.size() > sampler.size()) return Expected::type;
  return Expected::nothing;
}

// The orientation words that may end the annotation of `word` at argument `index` (docs/language.md, "Orientation").
std::vector<std::string> orientation_words(std::string_view word, int index) {
  if (word == "point" && index == 1) return {"shaded"};
  if ((word == "direction" && index == 1) || (word == "vector" && (index == 1 || index == 2))) return {"away", "toward"};
  return {};
}

// The first word of the statement that ends before `end`.
std::string_view statement_word(std::string_view text, std::size_t end) {
  std::size_t begin = end;
  while (begin > 0 && text[begin - 1] != ';' && text[begin - 1] != '{' && text[begin - 1] != '}') --begin;
  while (begin < end && !word_char(text[begin])) ++begin;
  std::size_t stop = begin;
  while (stop < end && word_char(text[stop])) ++stop;
  return text.substr(begin, stop - begin);
}

}  // namespace

CompletionContext completion_context(std::string_view text, std::size_t offset) {
  CompletionContext context;
  offset = std::min(offset, text.size());
  std::size_t start = offset;
  while (start > 0 && word_char(text[start - 1])) --start;
  context.prefix = std::string(text.substr(start, offset - start));
  // Back to the `<` of the annotation the cursor is in, counting the commas
  // of that list; a statement's end, a brace or an `=` stops the search.
  constexpr std::size_t kLookBack = 1024;
  int angles = 0, parens = 0, index = 0;
  for (std::size_t i = start; i > 0 && start - i < kLookBack; --i) {
    const char c = text[i - 1];
    if (c == ';' || c == '{' || c == '}') break;
    if (c == '=' || c == ':') {
      // `dimension area = len…`, `unit inch : len…`: a dimension expression.
      const std::string_view first = statement_word(text, i - 1);
      if ((c == '=' && first == "dimension") || (c == ':' && first == "unit")) {
        context.expected = Expected::dimension;
        return context;
      }
      break;
    }
    if (c == '>') ++angles;
    else if (c == ')') ++parens;
    else if (c == '(' && parens > 0) --parens;
    else if (c == ',' && angles == 0 && parens == 0) ++index;
    else if (c == '<') {
      if (angles > 0) {
        --angles;
        continue;
      }
      std::size_t end = i - 1;
      const std::string_view word = word_before(text, end);
      context.expected = annotation_argument(word, index);
      context.orientations = orientation_words(word, index);
      return context;
    }
  }
  // `3.0 * cent…`: a unit.
  std::size_t before = start;
  while (before > 0 && (text[before - 1] == ' ' || text[before - 1] == '\t')) --before;
  if (before > 0 && (text[before - 1] == '*' || text[before - 1] == '/')) context.expected = Expected::unit;
  return context;
}

namespace {

struct Vocabulary {
  std::set<std::string> dimensions, units, spaces, dimension_parameters, space_parameters;
};

// Declarations at global scope of the preprocessed text, and the template
// parameters of the function around `offset` of the document.
Vocabulary scan(const std::vector<Token>& tokens, FileId document, std::size_t offset) {
  Vocabulary v;
  struct Header {
    std::vector<std::pair<bool, std::string>> params;  // (a dimension parameter, name)
    std::size_t begin = 0;
    bool in_document = false;
    bool body_open = false;
  };
  std::optional<Header> header;  // the template header whose function is being read
  std::optional<Header> found;
  auto name_after = [&](std::size_t i) -> std::string {
    return i + 1 < tokens.size() && tokens[i + 1].kind == TokenKind::identifier ? std::string(tokens[i + 1].text) : "";
  };
  auto function_ends = [&](const Token& t) {
    if (header->in_document && offset >= header->begin && offset <= t.range.end.offset) found = header;
    header.reset();
  };
  int depth = 0;
  bool statement_start = true;
  for (std::size_t i = 0; i < tokens.size() && tokens[i].kind != TokenKind::eof; ++i) {
    const Token& t = tokens[i];
    const std::string_view text = t.text;
    const bool at_start = statement_start;
    statement_start = false;
    if (depth == 0 && at_start && t.kind == TokenKind::identifier && !name_after(i).empty()) {
      if (text == "dimension") v.dimensions.insert(name_after(i));
      else if (text == "unit") v.units.insert(name_after(i));
      else if (text == "space") v.spaces.insert(name_after(i));
    }
    if (depth == 0 && text == "template" && i + 1 < tokens.size() && tokens[i + 1].text == "<") {
      header.emplace();
      header->begin = t.range.begin.offset;
      header->in_document = t.range.begin.file == document;
      for (i += 2; i < tokens.size() && tokens[i].text != ">" && tokens[i].kind != TokenKind::eof; ++i)
        if ((tokens[i].text == "dimension" || tokens[i].text == "space") && !name_after(i).empty()) {
          header->params.emplace_back(tokens[i].text == "dimension", name_after(i));
          ++i;
        }
      continue;
    }
    if (text == "{") {
      if (depth++ == 0 && header) header->body_open = true;
    } else if (text == "}") {
      depth = std::max(0, depth - 1);
      statement_start = depth == 0;
      if (depth == 0 && header && header->body_open) function_ends(t);
    } else if (text == ";") {
      statement_start = depth == 0;
      if (depth == 0 && header && !header->body_open) function_ends(t);  // a prototype
    }
  }
  // A function still open at the end (being typed) holds the cursor if it started before it.
  if (header && header->in_document && offset >= header->begin) found = header;
  if (found)
    for (const auto& [dimension, name] : found->params) (dimension ? v.dimension_parameters : v.space_parameters).insert(name);
  return v;
}

json item(const std::string& label, int kind, const std::string& detail) {
  json out{{"label", label}, {"kind", kind}};
  if (!detail.empty()) out["detail"] = detail;
  return out;
}

}  // namespace

json completion(const std::string& path, const std::string& text, std::size_t offset, const CompileOptions& options,
                const DimensionRegistry* registry) {
  const CompletionContext context = completion_context(text, offset);
  json items = json::array();
  for (const std::string& o : context.orientations)
    items.push_back(item(o, completion_kind::keyword, o == "shaded" ? "the point being shaded" : "orientation relative to the shaded point"));
  if (context.expected == Expected::nothing || context.expected == Expected::orientation)
    return {{"isIncomplete", false}, {"items", items}};
  if (context.expected == Expected::template_parameter_kind) {
    items.push_back(item("dimension", completion_kind::keyword, "a dimension parameter"));
    items.push_back(item("space", completion_kind::keyword, "a space parameter"));
    return {{"isIncomplete", false}, {"items", items}};
  }
  if (context.expected == Expected::type) {
    for (const char* type : {"float", "vec2", "vec3", "vec4", "spectrum"})
      items.push_back(item(type, completion_kind::struct_, "texel type"));
    return {{"isIncomplete", false}, {"items", items}};
  }
  SourceManager sources;
  DiagnosticEngine diagnostics;
  const FileId file = sources.add_file(path, text);
  const PreprocessedUnit unit = preprocess(sources, file, preprocessor_options(options), diagnostics);
  const Vocabulary v = scan(unit.tokens, file, offset);
  if (context.expected == Expected::dimension) {
    for (const std::string& d : v.dimension_parameters) items.push_back(item(d, completion_kind::type_parameter, "dimension parameter"));
    for (const std::string& d : v.dimensions) {
      std::string detail = "dimension";
      if (registry) {
        if (registry->find_base(d)) detail = "base dimension — " + registry->format_si(*registry->find_dimension(d));
        else if (std::optional<Dimension> value = registry->find_dimension(d)) detail = "dimension — " + registry->format_si(*value);
      }
      items.push_back(item(d, completion_kind::class_, detail));
    }
  } else if (context.expected == Expected::space) {
    for (const std::string& s : v.space_parameters) items.push_back(item(s, completion_kind::type_parameter, "space parameter"));
    for (const std::string& s : v.spaces) items.push_back(item(s, completion_kind::module, "space"));
  } else if (context.expected == Expected::unit) {
    for (const std::string& u : v.units) {
      std::string detail = "unit";
      if (const Unit* found = registry ? registry->find_unit(u) : nullptr) {
        detail = "unit of " + registry->format(found->dimension) + " = " + DimensionRegistry::format_number(found->scale) + " " +
                 registry->format_si(found->dimension);
      }
      items.push_back(item(u, completion_kind::unit, detail));
    }
  }
  return {{"isIncomplete", false}, {"items", items}};
}

}  // namespace safegi::lsp
