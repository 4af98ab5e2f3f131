#pragma once
// Owns every byte of source a compilation reads, plus the bookkeeping that
// lets a diagnostic say where text came from: which file included which,
// which macro expansion produced a token, and what `#line` renamed.
//
// One SourceManager per compilation; it is not shared between threads.

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <safegi/diagnostics/source_location.hpp>

namespace safegi {

// One macro expansion: `name` defined at `definition`, expanded at
// `expansion_site` (the macro name through the closing parenthesis). When the
// expansion happened while rescanning another macro's replacement, `parent` is
// that outer expansion.
struct MacroExpansion {
  std::string_view name;
  SourceRange definition;
  SourceRange expansion_site;
  ExpansionId parent = kNoExpansion;
};

// What the user sees as the file and line of a location after `#line`.
struct PresumedLocation {
  std::string_view file_name;
  std::uint32_t line = 0;
  std::uint32_t column = 0;
  std::optional<std::uint32_t> source_string;  // `#line N S`: GLSL's source-string number
};

class SourceManager {
 public:
  SourceManager();
  ~SourceManager();
  SourceManager(const SourceManager&) = delete;
  SourceManager& operator=(const SourceManager&) = delete;

  // Registers `contents` under the display name `path`.
  FileId add_file(std::string path, std::string contents);

  // Reads a file from disk. On failure returns nullopt and, when given,
  // sets *error to a one-line reason ("No such file or directory").
  std::optional<FileId> load_file(const std::string& path, std::string* error = nullptr);

  // A second view of an existing file's buffer, for a file included twice:
  // each inclusion gets its own FileId and so its own include position.
  FileId add_inclusion(FileId file, SourceRange included_at);

  std::size_t file_count() const;
  bool valid(FileId file) const;
  std::string_view text(FileId file) const;
  const std::string& path(FileId file) const;
  std::uint32_t line_count(FileId file) const;
  // Line `line` (1-based) without its line terminator; empty if out of range.
  std::string_view line_text(FileId file, std::uint32_t line) const;
  // Offset clamped to the file's size.
  SourceLocation location_of(FileId file, std::uint32_t offset) const;
  SourceRange range_of(FileId file, std::uint32_t begin_offset, std::uint32_t end_offset) const;
  // location_of for callers walking a file forwards (the lexer): `line_hint`
  // is the line of an earlier offset, updated to this one's; O(1) per step.
  SourceLocation location_after(FileId file, std::uint32_t offset, std::uint32_t& line_hint) const;

  // Include stack: where `file` was included from (invalid range for a main file).
  void set_included_from(FileId file, SourceRange directive);
  SourceRange included_from(FileId file) const;
  // Outermost first: the directive ranges that led to `file`.
  std::vector<SourceRange> include_chain(FileId file) const;

  // Macro expansion table.
  ExpansionId add_expansion(MacroExpansion expansion);
  const MacroExpansion& expansion(ExpansionId id) const;
  std::size_t expansion_count() const;

  // `#line`: from byte `offset` of `file` on, the next physical line is
  // reported as `line`, optionally under a new name / source-string number.
  void add_line_directive(FileId file, std::uint32_t offset, std::uint32_t line,
                          std::optional<std::string> file_name,
                          std::optional<std::uint32_t> source_string);
  PresumedLocation presumed(SourceLocation location) const;

  // Stable storage: the returned view stays valid as long as this manager.
  std::string_view save_string(std::string_view text);

 private:
  struct LineDirective {
    std::uint32_t offset;
    std::uint32_t physical_line;  // line the directive's effect starts at
    std::uint32_t line;
    std::string_view file_name;  // empty: unchanged
    std::optional<std::uint32_t> source_string;
  };
  struct File {
    std::string path;
    std::shared_ptr<const std::string> contents;
    std::shared_ptr<const std::vector<std::uint32_t>> line_starts;
    SourceRange included_from;
    std::vector<LineDirective> line_directives;  // sorted by offset
  };
  const File& file(FileId id) const;

  std::vector<File> files_;  // index = FileId - 1
  std::vector<MacroExpansion> expansions_;  // index = ExpansionId - 1
  std::deque<std::string> strings_;
};

}  // namespace safegi
