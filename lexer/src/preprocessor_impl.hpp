#pragma once
// The preprocessor's state, shared by its source files (preprocessor.cpp:
// files, conditionals and output; directives.cpp: the other directives;
// macro_expansion.cpp: macro replacement). Not installed.

#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <safegi/diagnostics/codes.hpp>
#include <safegi/lexer/lexer.hpp>
#include <safegi/lexer/preprocessor.hpp>

#include "preprocessor_internal.hpp"

namespace safegi::detail {

// The preprocessor of one compilation; preprocess() makes one per call.
class Preprocessor {
 public:
  Preprocessor(SourceManager& sources, const PreprocessorOptions& options, DiagnosticEngine& diagnostics)
      : sources_(sources), options_(options), diagnostics_(diagnostics) {}

  PreprocessedUnit run(FileId main_file);

 private:
  // One file being read (the main file, an include, or the -D/-U prelude).
  struct FileState {
    FileState(SourceManager& s, FileId f, DiagnosticEngine& d, std::string p)
        : file(f), path(std::move(p)), lexer(s, f, d, LexerOptions{KeywordContext{}, false, false, false}) {}
    FileId file;
    std::string path;
    Lexer lexer;
    std::optional<Token> peeked;
    std::size_t conditional_base = 0;
    bool is_main = false;
    bool is_command_line = false;
    // What __FILE__ gives: the last `#line N S` source-string number, or the
    // last `#line N "name"` (GL_GOOGLE_cpp_style_line_directive) as a string.
    std::uint32_t source_string = 0;
    std::string_view line_file_name;
  };
  struct Conditional {
    SourceRange directive;
    bool taken = false;      // some group of this #if chain was (or is being) taken
    bool seen_else = false;
  };
  // Tokens to read before the files: macro replacement lists being rescanned.
  struct Buffer {
    std::vector<PPToken> tokens;
    std::size_t pos = 0;
    Macro* macro = nullptr;  // re-enabled when the buffer is left
  };
  struct Stream {
    std::vector<Buffer> buffers;
    bool from_files = false;  // the main stream continues into the files; lists end
  };

  // --- files and directives ---
  Token get(FileState& f);
  void unget(FileState& f, Token t) { f.peeked = t; }
  std::vector<Token> read_line(FileState& f);
  // read_line for a directive, recorded in PreprocessedUnit::directives.
  std::vector<Token> read_directive_line(FileState& f, DirectiveKind kind, const Token& hash);
  PPToken read_file_token();
  void handle_directive(FileState& f, const Token& hash);
  void skip_group(FileState& f);
  void end_of_file(FileState& f);
  void record_directive(DirectiveKind kind, const Token& hash, SourceLocation last_end);
  // Input that is plainly not text (an image, an object file, UTF-16): one error at its first
  // NUL or control byte (E-NOT-TEXT), and true, so the file is not lexed (a megabyte of random
  // bytes would otherwise be thousands of diagnostics).
  bool refuse_non_text(FileId file);
  std::uint32_t line_end_offset(SourceLocation at) const;
  void set_skipping(bool skipping);
  // From '#' to the last token of the line, at least through the directive's name.
  SourceRange directive_range(const Token& hash, const std::vector<Token>& line) const {
    SourceLocation end = line.empty() ? directive_name_end_ : line.back().range.end;
    if (end.file != hash.range.begin.file || end.offset < hash.range.end.offset) end = hash.range.end;
    return SourceRange{hash.range.begin, end};
  }

  void directive_define(FileState& f, const Token& hash);
  void directive_undef(FileState& f, const Token& hash);
  void directive_if(FileState& f, const Token& hash, DirectiveKind kind);
  void directive_elif_else_endif(FileState& f, const Token& hash, DirectiveKind kind);
  void directive_version(FileState& f, const Token& hash);
  void directive_extension(FileState& f, const Token& hash);
  void directive_pragma(FileState& f, const Token& hash);
  void directive_line(FileState& f, const Token& hash);
  void directive_error(FileState& f, const Token& hash, const Token& name);
  void directive_include(FileState& f, const Token& hash, const Token& name);
  bool evaluate_condition(const std::vector<Token>& line, const Token& hash);
  void extra_tokens_warning(const std::vector<Token>& line, std::size_t from, std::string_view directive);
  bool check_macro_name(const Token& name, bool defining, bool command_line);

  // --- version ---
  void note_content(const FileState& f);
  void apply_version();
  void define_predefined(std::string_view name, std::string_view value, Macro::Builtin builtin = Macro::Builtin::none);

  // --- macro expansion ---
  PPToken next_unexpanded(Stream& s);
  void push_back(Stream& s, PPToken t);
  PPToken next_expanded(Stream& s, ExpansionId default_parent, int depth);
  bool expand_macro(Stream& s, Macro& m, const PPToken& name, ExpansionId default_parent, int depth);
  std::vector<PPToken> expand_list(std::vector<PPToken> tokens, ExpansionId default_parent, int depth);
  std::optional<PPToken> paste(const PPToken& lhs, const PPToken& rhs, const Token& op);
  Macro* find_macro(std::string_view name);
  PPToken builtin_value(const Macro& m, const PPToken& name);
  bool over_budget(std::size_t more);

  void emit(const PPToken& t);
  std::string_view save(std::string s) { return sources_.save_string(s); }
  // Every diagnostic of the preprocessor has its code (codes.def).
  void error(const char* code, SourceRange range, std::string message) {
    diagnostics_.report(Diagnostic::error(range, std::move(message)).with_code(code));
  }

  SourceManager& sources_;
  const PreprocessorOptions& options_;
  DiagnosticEngine& diagnostics_;
  PreprocessedUnit unit_;

  std::vector<std::unique_ptr<FileState>> files_;
  std::vector<Conditional> conditionals_;
  bool skipping_ = false;
  std::unordered_map<std::string_view, std::unique_ptr<Macro>> macros_;
  // The first bytes and lengths (63 and longer share a bit) macro names have had: a word with
  // another first byte or length is no macro, found without hashing it (find_macro, most words).
  std::uint64_t macro_initials_[4] = {0, 0, 0, 0};
  std::uint64_t macro_lengths_ = 0;
  void add_macro(std::string_view name, std::unique_ptr<Macro> macro) {
    const auto initial = name.empty() ? 0u : static_cast<unsigned char>(name[0]);
    macro_initials_[initial >> 6] |= std::uint64_t{1} << (initial & 63u);
    macro_lengths_ |= std::uint64_t{1} << std::min<std::size_t>(name.size(), 63);
    macros_.emplace(name, std::move(macro));
  }
  std::unordered_map<std::string, FileId> loaded_files_;
  std::unordered_set<std::string> once_files_;
  Stream main_stream_{{}, true};
  bool strings_allowed_ = false;  // GL_EXT_debug_printf enabled
  bool saw_content_ = false;  // a token or non-#version directive in the main file
  bool version_applied_ = false;
  bool aborted_ = false;     // a limit was hit; wind down
  std::size_t produced_tokens_ = 0;
  SourceLocation last_location_;  // of the last token read from a file, for __LINE__
  SourceLocation directive_name_end_;  // end of the current directive's name ("#define")
  std::string_view file_name_macro_ = "__FILE__";
};

}  // namespace safegi::detail
