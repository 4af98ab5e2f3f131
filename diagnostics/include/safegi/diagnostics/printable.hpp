#pragma once
// Input files may hold any byte, and diagnostics quote them (a source line, a
// token in a message, a file name). A terminal executes the control bytes it
// is sent (ESC sequences recolour it, move the cursor, retitle the window) and
// an editor renders what the language server reports, so every program prints
// input text through these functions: each byte that is not printable text is
// written as \xHH, which takes four columns.

#include <cstddef>
#include <string>
#include <string_view>

namespace safegi {

// One character of a text: a well-formed UTF-8 sequence, or one byte.
struct TextUnit {
  std::size_t bytes = 1;
  bool printable = true;  // false: C0 and C1 controls, DEL, bytes that are not UTF-8, bidirectional overrides
  bool utf8 = true;       // false: a byte that starts no well-formed UTF-8 sequence
};

// The unit that starts at text[at] (at < text.size()).
TextUnit text_unit_at(std::string_view text, std::size_t at);

// Appends the unit's bytes as \xHH each (what an unprintable unit is shown as).
void append_escaped(std::string& out, std::string_view unit);

// `text` with every unprintable unit escaped; tabs and line breaks too, unless
// `keep_line_breaks` (for text that is already a whole diagnostic, lines and all).
std::string escape_unprintable(std::string_view text, bool keep_line_breaks = false);

// `text` with every byte that is not UTF-8 escaped as \xHH and everything else, controls
// too, as it is: for text that must be UTF-8 (a diagnostic bound for JSON) and is escaped
// for a terminal when printed (escape_unprintable). One validator for both (RFC 3629).
std::string escape_invalid_utf8(std::string_view text);

// What a program prints for an error it caught, as a line on stderr. A text
// ending in a newline is a whole diagnostic already ("file:line:col: error: …"
// with its source line and caret: the pbrt importer's, the compiler's) and
// keeps its lines; anything else becomes "error: <text>\n". Either way every
// unprintable byte is escaped, so that a NUL cannot cut the text short and
// no input byte reaches the terminal raw.
std::string error_report(std::string_view what);

// What a program says when an allocation failed (a std::bad_alloc reached its
// top level): "out of memory while <doing>: an allocation failed (std::bad_alloc)".
std::string out_of_memory_text(std::string_view doing);

}  // namespace safegi
