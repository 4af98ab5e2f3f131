#include <safegi/diagnostics/render.hpp>

#include <safegi/diagnostics/printable.hpp>

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

// A quoted source line with tabs expanded and unprintable bytes escaped, plus
// the display column at which each byte of the original line starts (one
// extra entry for end of line); the bytes of one character share its column.
struct QuotedLine {
  std::string text;
  std::vector<std::size_t> column_of_byte;
  std::vector<std::size_t> text_offset_of_column;  // where each column's text begins (one extra: the end)
  std::vector<bool> starts_character;              // per column: a character (or tab, or escape) begins there
  std::size_t columns_so_far() const { return text_offset_of_column.size(); }
  std::size_t columns() const { return column_of_byte.back(); }
};

QuotedLine quote_line(std::string_view line, unsigned tab_width) {
  QuotedLine quoted;
  quoted.column_of_byte.reserve(line.size() + 1);
  for (std::size_t at = 0; at < line.size();) {
    const TextUnit unit = text_unit_at(line, at);
    const std::string_view bytes = line.substr(at, unit.bytes);
    const std::size_t column = quoted.columns_so_far(), before = quoted.text.size();
    quoted.column_of_byte.insert(quoted.column_of_byte.end(), unit.bytes, column);
    // A character is one column however many bytes it has; tab stops and escapes are one byte a column.
    bool one_column = false;
    if (bytes == "\t") {
      one_column = tab_width == 0;  // tab_width 0: tabs are quoted as they are
      if (one_column) quoted.text += bytes;
      else quoted.text.append(tab_width - column % tab_width, ' ');
    } else if (!unit.printable) {
      append_escaped(quoted.text, bytes);
    } else {
      quoted.text += bytes;
      one_column = true;
    }
    if (one_column) quoted.text_offset_of_column.push_back(before);
    else
      for (std::size_t offset = before; offset < quoted.text.size(); ++offset) quoted.text_offset_of_column.push_back(offset);
    quoted.starts_character.resize(quoted.columns_so_far(), false);
    quoted.starts_character[column] = true;
    at += unit.bytes;
  }
  quoted.column_of_byte.push_back(quoted.columns_so_far());
  quoted.text_offset_of_column.push_back(quoted.text.size());
  quoted.starts_character.push_back(true);
  return quoted;
}

// The byte columns of `range` on `line`, as offsets into the quoted part of the
// line, which begins at byte `skipped` of it.
std::size_t quoted_byte(std::size_t column, std::size_t skipped, std::size_t last_byte) {
  return column - 1 < skipped ? 0 : std::min<std::size_t>(column - 1 - skipped, last_byte);
}

// Marks the part of `range` that lies on `line` of `file` with `mark`.
void mark_range(std::string& carets, const QuotedLine& quoted, SourceRange range, FileId file,
                std::uint32_t line, char mark, std::size_t skipped) {
  if (range.begin.file != file || range.begin.line > line || range.end.line < line) return;
  std::size_t last_byte = quoted.column_of_byte.size() - 1;
  std::size_t first = range.begin.line == line ? quoted_byte(range.begin.column, skipped, last_byte) : 0;
  std::size_t end = range.end.line == line ? quoted_byte(range.end.column, skipped, last_byte) : last_byte;
  std::size_t from = quoted.column_of_byte[first];
  std::size_t to = quoted.column_of_byte[std::max(first, end)];
  if (carets.size() < to) carets.resize(to, ' ');
  for (std::size_t c = from; c < to; ++c) {
    if (carets[c] != '^') carets[c] = mark;
  }
}

constexpr std::string_view kElided = "...";

// The columns [begin, end) of a quoted line shown when it is wider than
// `max_columns`: the caret and as much of its underline as fits, centred, the
// rest of the room on either side; each side that is cut costs "..." of it.
struct ColumnWindow {
  std::size_t begin, end;
};

ColumnWindow window_around(std::size_t caret, std::size_t underline_end, std::size_t columns, std::size_t max_columns) {
  if (max_columns == 0 || columns <= max_columns) return {0, columns};
  const std::size_t room = max_columns > 2 * kElided.size() ? max_columns - 2 * kElided.size() : 1;
  const std::size_t wanted = std::min(std::max(underline_end, caret + 1) - caret, room);
  std::size_t begin = caret - std::min(caret, (room - wanted) / 2);
  std::size_t end = std::min(columns, begin + room);
  begin = end - std::min(end, room);
  // A side that is not cut needs no "...": give its room to the other side.
  if (begin == 0) end = std::min(columns, end + kElided.size());
  if (end == columns) begin -= std::min(begin, kElided.size());
  return {begin, end};
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
      out_ += escape_unprintable(d.hint);
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
    out_ += escape_unprintable(message);
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
    // Only the bytes around the caret are quoted, so a diagnostic costs the same on a line of a
    // megabyte: every byte is at least one column, so this many bytes on each side fill the window.
    std::string_view text = sources_.line_text(file, line);
    std::size_t skipped = 0;
    bool cut_before = false, cut_after = false;
    if (const std::size_t reach = 2 * style_.max_line_columns + 16; style_.max_line_columns != 0 && text.size() > 2 * reach) {
      const std::size_t caret_byte = std::min<std::size_t>(range.begin.column - 1, text.size());
      skipped = caret_byte - std::min(caret_byte, reach);
      while (skipped > 0 && (static_cast<unsigned char>(text[skipped]) & 0xC0) == 0x80) --skipped;  // not inside a character
      const std::size_t end = std::min(text.size(), caret_byte + reach);
      cut_before = skipped > 0;
      cut_after = end < text.size();
      text = text.substr(skipped, end - skipped);
    }
    QuotedLine quoted = quote_line(text, style_.tab_width);
    std::string carets;
    for (SourceRange h : highlights) mark_range(carets, quoted, h, file, line, '~', skipped);
    mark_range(carets, quoted, range, file, line, '~', skipped);
    std::size_t first = quoted_byte(range.begin.column, skipped, quoted.column_of_byte.size() - 1);
    std::size_t caret = quoted.column_of_byte[first];
    if (carets.size() <= caret) carets.resize(caret + 1, ' ');
    carets[caret] = '^';
    while (!carets.empty() && carets.back() == ' ') carets.pop_back();
    quote(quoted, carets, caret, cut_before, cut_after);
  }

  // The line and its carets, cut to the style's width around the caret; `cut_before` /
  // `cut_after`: `quoted` is already a part of the line.
  void quote(const QuotedLine& quoted, const std::string& carets, std::size_t caret, bool already_cut_before,
             bool already_cut_after) {
    std::size_t underline_end = caret + 1;
    while (underline_end < carets.size() && carets[underline_end] == '~') ++underline_end;
    // The caret may stand just past the last character: its column counts as part of the line.
    const std::size_t columns = std::max(quoted.columns(), caret + 1);
    ColumnWindow shown = window_around(caret, underline_end, columns, style_.max_line_columns);
    // Cut between characters, never inside an escape such as \x1B.
    const auto starts_character = [&](std::size_t column) {
      return column >= quoted.columns() || quoted.starts_character[column];
    };
    while (!starts_character(shown.begin)) ++shown.begin;
    while (shown.end > caret + 1 && !starts_character(shown.end)) --shown.end;
    const bool cut_before = shown.begin > 0 || already_cut_before, cut_after = shown.end < columns || already_cut_after;
    const auto text_at = [&](std::size_t column) {
      return quoted.text_offset_of_column[std::min(column, quoted.columns())];
    };
    if (cut_before) out_ += kElided;
    out_.append(quoted.text, text_at(shown.begin), text_at(shown.end) - text_at(shown.begin));
    if (cut_after) out_ += kElided;
    out_ += '\n';
    std::string caret_line(cut_before ? kElided.size() : 0, ' ');
    if (shown.begin < carets.size()) caret_line.append(carets, shown.begin, std::min(carets.size(), shown.end) - shown.begin);
    while (!caret_line.empty() && caret_line.back() == ' ') caret_line.pop_back();
    paint(kCaretColor);
    out_ += caret_line;
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
  return escape_unprintable(p.file_name) + ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
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
