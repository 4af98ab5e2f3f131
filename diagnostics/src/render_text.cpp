#include <safegi/diagnostics/render.hpp>

#include <algorithm>
#include <string_view>

namespace safegi {
namespace {

constexpr std::string_view kReset = "\x1b[0m";
constexpr std::string_view kBold = "\x1b[1m";
constexpr std::string_view kCaretColor = "\x1b[1;32m";

std::string_view severity_color(Severity severity) {
  switch (severity) {
    case Severity::error: return "\x1b[1;31m";
    case Severity::warning: return "\x1b[1;35m";
    case Severity::note: return "\x1b[1;36m";
  }
  return kBold;
}

bool is_utf8_continuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// A quoted source line with tabs expanded, plus the display column at which
// each byte of the original line starts (one extra entry for end of line).
struct QuotedLine {
  std::string text;
  std::vector<std::size_t> column_of_byte;
};

QuotedLine quote_line(std::string_view line, unsigned tab_width) {
  QuotedLine quoted;
  quoted.column_of_byte.reserve(line.size() + 1);
  std::size_t column = 0;
  for (char c : line) {
    quoted.column_of_byte.push_back(column);
    if (c == '\t' && tab_width != 0) {
      std::size_t spaces = tab_width - column % tab_width;
      quoted.text.append(spaces, ' ');
      column += spaces;
    } else {
      quoted.text.push_back(c);
      if (!is_utf8_continuation(c)) ++column;
    }
  }
  quoted.column_of_byte.push_back(column);
  return quoted;
}

// Marks the part of `range` that lies on `line` of `file` with `mark`.
void mark_range(std::string& carets, const QuotedLine& quoted, SourceRange range, FileId file,
                std::uint32_t line, char mark) {
  if (range.begin.file != file || range.begin.line > line || range.end.line < line) return;
  std::size_t last_byte = quoted.column_of_byte.size() - 1;
  std::size_t first = range.begin.line == line ? std::min<std::size_t>(range.begin.column - 1, last_byte) : 0;
  std::size_t end = range.end.line == line ? std::min<std::size_t>(range.end.column - 1, last_byte) : last_byte;
  std::size_t from = quoted.column_of_byte[first];
  std::size_t to = quoted.column_of_byte[std::max(first, end)];
  if (carets.size() < to) carets.resize(to, ' ');
  for (std::size_t c = from; c < to; ++c) {
    if (carets[c] != '^') carets[c] = mark;
  }
}

class TextRenderer {
 public:
  TextRenderer(const SourceManager& sources, TextStyle style) : sources_(sources), style_(style) {}

  void render(const Diagnostic& d, FileId outer_file) {
    if (d.range.valid() && sources_.valid(d.range.begin.file) && d.range.begin.file != outer_file) {
      for (SourceRange at : sources_.include_chain(d.range.begin.file)) {
        out_ += "In file included from " + location(at.begin) + ":\n";
      }
    }
    header(d.severity, d.range.begin, d.message, d.code);
    snippet(d.range, d.highlights);
    expansion_chain(d.expansion);
    if (!d.hint.empty()) {
      paint(kBold);
      out_ += "help: ";
      paint(kReset);
      out_ += d.hint;
      out_ += '\n';
    }
    FileId file = d.range.valid() ? d.range.begin.file : outer_file;
    for (const Diagnostic& note : d.notes) render(note, file);
  }

  std::string take() { return std::move(out_); }

 private:
  void paint(std::string_view code) {
    if (style_.color) out_ += code;
  }

  std::string location(SourceLocation at) const { return format_location(at, sources_); }

  void header(Severity severity, SourceLocation at, std::string_view message, std::string_view code) {
    paint(kBold);
    if (at.valid() && sources_.valid(at.file)) out_ += location(at) + ": ";
    paint(severity_color(severity));
    out_ += severity_name(severity);
    out_ += ": ";
    paint(kReset);
    paint(kBold);
    out_ += message;
    if (!code.empty()) {
      out_ += " [";
      out_ += code;
      out_ += ']';
    }
    paint(kReset);
    out_ += '\n';
  }

  void snippet(SourceRange range, const std::vector<SourceRange>& highlights) {
    if (!range.valid() || !sources_.valid(range.begin.file)) return;
    FileId file = range.begin.file;
    std::uint32_t line = range.begin.line;
    if (line == 0 || line > sources_.line_count(file)) return;
    QuotedLine quoted = quote_line(sources_.line_text(file, line), style_.tab_width);
    std::string carets;
    for (SourceRange h : highlights) mark_range(carets, quoted, h, file, line, '~');
    mark_range(carets, quoted, range, file, line, '~');
    std::size_t first = std::min<std::size_t>(range.begin.column - 1, quoted.column_of_byte.size() - 1);
    std::size_t caret = quoted.column_of_byte[first];
    if (carets.size() <= caret) carets.resize(caret + 1, ' ');
    carets[caret] = '^';
    while (!carets.empty() && carets.back() == ' ') carets.pop_back();
    out_ += quoted.text;
    out_ += '\n';
    paint(kCaretColor);
    out_ += carets;
    paint(kReset);
    out_ += '\n';
  }

  void expansion_chain(ExpansionId id) {
    // Each level was created before its children, so ids strictly decrease
    // along the chain; the bound only guards against a corrupted table.
    for (std::size_t depth = 0; id != kNoExpansion && depth <= sources_.expansion_count(); ++depth) {
      const MacroExpansion& e = sources_.expansion(id);
      std::string message = "in expansion of macro '" + std::string(e.name) + "'";
      if (e.definition.valid()) message += " (defined at " + location(e.definition.begin) + ")";
      header(Severity::note, e.expansion_site.begin, message, {});
      snippet(e.expansion_site, {});
      id = e.parent;
    }
  }

  const SourceManager& sources_;
  TextStyle style_;
  std::string out_;
};

}  // namespace

std::string format_location(SourceLocation at, const SourceManager& sources) {
  if (!at.valid() || !sources.valid(at.file)) return "<unknown>";
  PresumedLocation p = sources.presumed(at);
  return std::string(p.file_name) + ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
}

std::string render_text(const Diagnostic& diagnostic, const SourceManager& sources, TextStyle style) {
  TextRenderer renderer(sources, style);
  renderer.render(diagnostic, kNoFile);
  return renderer.take();
}

std::string render_text(const std::vector<Diagnostic>& diagnostics, const SourceManager& sources,
                        TextStyle style) {
  std::string out;
  for (const Diagnostic& d : diagnostics) out += render_text(d, sources, style);
  return out;
}

}  // namespace safegi
