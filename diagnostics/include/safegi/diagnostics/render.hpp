#pragma once
// Printing diagnostics: text in the clang/gcc style for people and tools that
// parse `file:line:col: error:`, JSON for editors.

#include <cstddef>
#include <string>
#include <vector>

#include <safegi/diagnostics/diagnostic.hpp>
#include <safegi/diagnostics/source_manager.hpp>

namespace safegi {

struct TextStyle {
  bool color = false;        // ANSI colours; only when the caller asks (a terminal)
  unsigned tab_width = 4;    // tabs in quoted source lines expand to this tab stop
  // A quoted source line wider than this (in columns) is cut to a window around
  // the caret, with "..." where text was left out (as clang does for its
  // message length); 0: never cut. One-line meshes and minified files would
  // otherwise quote megabytes.
  std::size_t max_line_columns = 160;
};

// One diagnostic with its source line, caret line, macro-expansion and
// include chains, hint and notes. Ends with a newline. Every byte of input text
// it quotes that is not printable (control bytes, malformed UTF-8: printable.hpp)
// is written as \xHH, in the source line, the messages and the file names; the
// caret stays under its character.
std::string render_text(const Diagnostic& diagnostic, const SourceManager& sources,
                        TextStyle style = {});
std::string render_text(const std::vector<Diagnostic>& diagnostics, const SourceManager& sources,
                        TextStyle style = {});

// JSON for editors; see docs/preprocessor.md for the schema. One object per
// diagnostic; the vector form gives {"diagnostics": [...]}.
std::string render_json(const Diagnostic& diagnostic, const SourceManager& sources);
std::string render_json(const std::vector<Diagnostic>& diagnostics, const SourceManager& sources);

// "a.glsl:3:7" using the presumed (#line-adjusted) location.
std::string format_location(SourceLocation location, const SourceManager& sources);

}  // namespace safegi
