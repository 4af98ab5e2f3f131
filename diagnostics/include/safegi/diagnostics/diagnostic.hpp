#pragma once
// Diagnostics are plain values: the stage that finds a problem builds one,
// the DiagnosticEngine of the compilation collects it, and the caller decides
// how to print (render.hpp) or inspect it.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <safegi/diagnostics/source_location.hpp>

namespace safegi {

enum class Severity { error, warning, note };

std::string_view severity_name(Severity severity);

struct Diagnostic {
  Severity severity = Severity::error;
  std::string message;
  SourceRange range;                     // caret at range.begin, `~` under the rest
  std::vector<SourceRange> highlights;   // extra underlines
  std::vector<Diagnostic> notes;         // rendered below, each in the same style
  std::string hint;                      // "help: ..."
  std::string code;                      // stable id (codes.def: code::E_DIMENSION_MISMATCH); empty on a note
  ExpansionId expansion = kNoExpansion;  // macro expansion that produced `range`, if any

  static Diagnostic error(SourceRange range, std::string message);
  static Diagnostic warning(SourceRange range, std::string message);
  static Diagnostic note(SourceRange range, std::string message);

  Diagnostic& with_note(Diagnostic note) &;
  Diagnostic&& with_note(Diagnostic note) &&;
  Diagnostic& with_highlight(SourceRange range) &;
  Diagnostic&& with_highlight(SourceRange range) &&;
  Diagnostic& with_hint(std::string hint) &;
  Diagnostic&& with_hint(std::string hint) &&;
  Diagnostic& with_code(std::string code) &;
  Diagnostic&& with_code(std::string code) &&;
  Diagnostic& with_expansion(ExpansionId expansion) &;
  Diagnostic&& with_expansion(ExpansionId expansion) &&;
};

struct DiagnosticOptions {
  bool warnings_as_errors = false;  // -Werror
  bool suppress_warnings = false;   // -w
  std::size_t error_limit = 0;      // stop after this many errors; 0 = no limit
};

// Collects the diagnostics of one compilation. No global state: make one per
// compilation (or per thread).
class DiagnosticEngine {
 public:
  DiagnosticEngine() = default;
  explicit DiagnosticEngine(DiagnosticOptions options) : options_(options) {}

  // Records `diagnostic` after applying -Werror / -w; once the error limit is
  // reached the engine records one final "too many errors" note and ignores
  // everything after it.
  void report(Diagnostic diagnostic);
  void error(SourceRange range, std::string message);
  void warning(SourceRange range, std::string message);

  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
  std::size_t error_count() const { return error_count_; }
  std::size_t warning_count() const { return warning_count_; }
  bool has_errors() const { return error_count_ != 0; }
  // True once the error limit was hit: stages may stop early.
  bool limit_reached() const { return limit_reached_; }
  const DiagnosticOptions& options() const { return options_; }

  void clear();

 private:
  DiagnosticOptions options_;
  std::vector<Diagnostic> diagnostics_;
  std::size_t error_count_ = 0;
  std::size_t warning_count_ = 0;
  bool limit_reached_ = false;
};

}  // namespace safegi
