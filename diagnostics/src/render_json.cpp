#include <safegi/diagnostics/render.hpp>

#include <nlohmann/json.hpp>
#include <safegi/diagnostics/printable.hpp>

namespace safegi {
namespace {

using nlohmann::json;

json position(SourceLocation at) {
  return json{{"line", at.line}, {"column", at.column}, {"offset", at.offset}};
}

json range_json(SourceRange range, const SourceManager& sources) {
  if (!range.valid() || !sources.valid(range.begin.file)) return nullptr;
  PresumedLocation presumed = sources.presumed(range.begin);
  json r{{"file", sources.path(range.begin.file)},
         {"begin", position(range.begin)},
         {"end", position(range.end)}};
  // What `#line` made of the location, when it differs from the physical one.
  if (presumed.line != range.begin.line || presumed.file_name != sources.path(range.begin.file)) {
    r["presumed"] = json{{"file", presumed.file_name}, {"line", presumed.line}, {"column", presumed.column}};
  }
  return r;
}

// Editors show message and hint as text: an input's control bytes are escaped
// there as in the text renderer (JSON's own \u001b would reach the editor as ESC).
json diagnostic_json(const Diagnostic& d, const SourceManager& sources) {
  json j{{"severity", severity_name(d.severity)},
         {"message", escape_unprintable(d.message)},
         {"range", range_json(d.range, sources)}};
  if (!d.code.empty()) j["code"] = d.code;
  if (!d.hint.empty()) j["hint"] = escape_unprintable(d.hint);
  if (!d.highlights.empty()) {
    json& highlights = j["highlights"] = json::array();
    for (SourceRange h : d.highlights) highlights.push_back(range_json(h, sources));
  }
  if (d.range.valid() && sources.valid(d.range.begin.file)) {
    auto chain = sources.include_chain(d.range.begin.file);
    if (!chain.empty()) {
      json& included = j["included_from"] = json::array();
      for (SourceRange at : chain) included.push_back(range_json(at, sources));
    }
  }
  if (d.expansion != kNoExpansion) {
    json& expansions = j["expansions"] = json::array();
    ExpansionId id = d.expansion;
    for (std::size_t depth = 0; id != kNoExpansion && depth <= sources.expansion_count(); ++depth) {
      const MacroExpansion& e = sources.expansion(id);
      expansions.push_back(json{{"macro", e.name},
                                {"defined_at", range_json(e.definition, sources)},
                                {"expanded_at", range_json(e.expansion_site, sources)}});
      id = e.parent;
    }
  }
  if (!d.notes.empty()) {
    json& notes = j["notes"] = json::array();
    for (const Diagnostic& n : d.notes) notes.push_back(diagnostic_json(n, sources));
  }
  return j;
}

}  // namespace

std::string render_json(const Diagnostic& diagnostic, const SourceManager& sources) {
  return diagnostic_json(diagnostic, sources).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string render_json(const std::vector<Diagnostic>& diagnostics, const SourceManager& sources) {
  json list = json::array();
  for (const Diagnostic& d : diagnostics) list.push_back(diagnostic_json(d, sources));
  return json{{"diagnostics", std::move(list)}}.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace safegi
