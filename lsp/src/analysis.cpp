#include "analysis.hpp"

#include <safegi/compiler/compile.hpp>
#include <safegi/diagnostics/printable.hpp>
#include <safegi/diagnostics/render.hpp>

#include "documents.hpp"
#include "uri.hpp"

namespace safegi::lsp {

std::shared_ptr<const Analysis> analyze(const Document& document, CompileOptions options) {
  options.keep_analysis = true;
  ShaderSource source{document.path, document.text, stage_from_path(document.path)};
  // An unsaved buffer has no telling name; an editor's language id may say the stage ("frag").
  if (!source.stage) source.stage = stage_from_name(document.language_id);
  auto analysis = std::make_shared<Analysis>();
  analysis->result = compile({source}, options);
  return analysis;
}

// ------------------------------------------------------------------ Locator

Locator::Locator(const Document& document, const SourceManager& sources, Encoding encoding, std::string prelude_file)
    : document_(document), sources_(sources), encoding_(encoding), prelude_file_(std::move(prelude_file)) {}

bool Locator::in_document(FileId file) const { return sources_.valid(file) && !sources_.included_from(file).valid(); }

const LineIndex& Locator::lines(FileId file) const {
  auto it = lines_.find(file);
  if (it == lines_.end()) it = lines_.emplace(file, LineIndex(sources_.text(file))).first;
  return it->second;
}

std::optional<std::string> Locator::uri(FileId file) const {
  if (in_document(file)) return document_.uri;
  const std::string& path = sources_.path(file);
  if (path == kBuiltinPreludePath) {
    if (prelude_file_.empty()) return std::nullopt;
    return uri_from_path(prelude_file_);
  }
  if (path.rfind(kBuiltinIncludeDir, 0) == 0) return std::nullopt;
  return uri_from_path(path);
}

json Locator::range(SourceRange range) const {
  if (!range.valid() || !sources_.valid(range.begin.file)) return range_json({}, {});
  const LineIndex& index = lines(range.begin.file);
  const Position begin = index.position_of(range.begin.offset, encoding_);
  const bool same_file = range.end.file == range.begin.file && range.end.offset >= range.begin.offset;
  return range_json(begin, same_file ? index.position_of(range.end.offset, encoding_) : begin);
}

std::optional<json> Locator::location(SourceRange range) const {
  if (!range.valid() || !sources_.valid(range.begin.file)) return std::nullopt;
  std::optional<std::string> file = uri(range.begin.file);
  if (!file) return std::nullopt;
  return json{{"uri", *file}, {"range", this->range(range)}};
}

SourceRange Locator::in_document_range(SourceRange range) const {
  if (!range.valid() || !sources_.valid(range.begin.file) || in_document(range.begin.file)) return range;
  const std::vector<SourceRange> chain = sources_.include_chain(range.begin.file);
  return chain.empty() ? SourceRange{} : chain.front();  // outermost: the directive in the document
}

// -------------------------------------------------------------- diagnostics

namespace {

int severity_of(Severity s) {
  switch (s) {
    case Severity::error: return severity::error;
    case Severity::warning: return severity::warning;
    case Severity::note: return severity::information;
  }
  return severity::error;
}

struct Related {
  SourceRange range;
  std::string message;
  std::string_view label;  // "note", "help", "error": what the plain style prints before the message
};

// Notes, macro expansions and the hint of `d`, in the order the text renderer prints them.
std::vector<Related> related_of(const Diagnostic& d, const SourceManager& sources) {
  std::vector<Related> out;
  ExpansionId id = d.expansion;
  for (std::size_t depth = 0; id != kNoExpansion && depth <= sources.expansion_count(); ++depth) {
    const MacroExpansion& e = sources.expansion(id);
    out.push_back({e.expansion_site, "in expansion of macro '" + std::string(e.name) + "'", "note"});
    id = e.parent;
  }
  for (const Diagnostic& n : d.notes) out.push_back({n.range, escape_unprintable(n.message), "note"});
  if (!d.hint.empty()) out.push_back({d.range, "help: " + escape_unprintable(d.hint), "help"});
  return out;
}

json diagnostic_json(const Diagnostic& d, const Locator& locator, const SourceManager& sources, DiagnosticStyle style) {
  // Editors render message text: input bytes such as ESC are escaped, as safeglslc prints them.
  std::string message = escape_unprintable(d.message);
  std::vector<Related> related = related_of(d, sources);
  const SourceRange shown = locator.in_document_range(d.range);
  if (d.range.valid() && shown != d.range) {
    // In an included file: said at the #include line, the real place first among the related.
    related.insert(related.begin(), {d.range, message, severity_name(d.severity)});
    message = "In included file: " + message;
  }
  json out{{"range", locator.range(shown)}, {"severity", severity_of(d.severity)}, {"source", "safeglslc"}};
  if (!d.code.empty()) out["code"] = d.code;
  if (style.related_information) {
    json list = json::array();
    for (const Related& r : related)
      if (std::optional<json> where = locator.location(r.range))
        list.push_back({{"location", *where}, {"message", r.message}});
      else
        message += "\n" + r.message;  // no place to point at (the built-in prelude): keep the words
    if (!list.empty()) out["relatedInformation"] = std::move(list);
  } else {
    // As safeglslc prints them: `file:line:col: note: …`, `help: …`.
    for (const Related& r : related) {
      if (r.label == "help") {
        message += "\n" + r.message;
        continue;
      }
      std::string where;
      if (r.range.valid() && sources.valid(r.range.begin.file)) where = format_location(r.range.begin, sources) + ": ";
      message += "\n" + where + std::string(r.label) + ": " + r.message;
    }
  }
  out["message"] = message;
  return out;
}

}  // namespace

json diagnostics_json(const Analysis& analysis, const Locator& locator, DiagnosticStyle style) {
  json list = json::array();
  if (!analysis.result.sources) return list;
  for (const Diagnostic& d : analysis.result.diagnostics)
    list.push_back(diagnostic_json(d, locator, *analysis.result.sources, style));
  return list;
}

}  // namespace safegi::lsp
