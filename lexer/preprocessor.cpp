#include <safegi/lexer/preprocessor.hpp>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include <safegi/lexer/lexer.hpp>

#include "preprocessor_internal.hpp"

namespace safegi {
namespace {

using detail::Macro;
using detail::PPToken;

bool starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

std::optional<std::string> read_from_disk(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return std::move(buffer).str();
}

bool is_known_version(int v) {
  switch (v) {
    case 100: case 110: case 120: case 130: case 140: case 150: case 300: case 310: case 320:
    case 330: case 400: case 410: case 420: case 430: case 440: case 450: case 460: return true;
    default: return false;
  }
}

DirectiveKind directive_kind(std::string_view name) {
  if (name == "define") return DirectiveKind::define;
  if (name == "undef") return DirectiveKind::undef;
  if (name == "if") return DirectiveKind::if_;
  if (name == "ifdef") return DirectiveKind::ifdef;
  if (name == "ifndef") return DirectiveKind::ifndef;
  if (name == "elif") return DirectiveKind::elif;
  if (name == "else") return DirectiveKind::else_;
  if (name == "endif") return DirectiveKind::endif;
  if (name == "version") return DirectiveKind::version;
  if (name == "extension") return DirectiveKind::extension;
  if (name == "pragma") return DirectiveKind::pragma;
  if (name == "line") return DirectiveKind::line;
  if (name == "error") return DirectiveKind::error;
  if (name == "include") return DirectiveKind::include;
  return DirectiveKind::unknown;
}

class Preprocessor {
 public:
  Preprocessor(SourceManager& sources, const PreprocessorOptions& options, DiagnosticEngine& diagnostics)
      : sources_(sources), options_(options), diagnostics_(diagnostics) {}

  PreprocessedUnit run(FileId main_file);

 private:
  // One file being read (the main file, an include, or the -D/-U prelude).
  struct FileState {
    FileState(SourceManager& s, FileId f, DiagnosticEngine& d, std::string p)
        : file(f), path(std::move(p)), lexer(s, f, d, LexerOptions{KeywordContext{}, false}) {}
    FileId file;
    std::string path;
    Lexer lexer;
    std::optional<Token> peeked;
    std::size_t conditional_base = 0;
    bool is_main = false;
    bool is_command_line = false;
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
  PPToken read_file_token();
  void handle_directive(FileState& f, const Token& hash);
  void skip_group(FileState& f);
  void end_of_file(FileState& f);
  void record_directive(DirectiveKind kind, const Token& hash, SourceLocation last_end);
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
  void error(SourceRange range, std::string message) { diagnostics_.error(range, std::move(message)); }

  SourceManager& sources_;
  const PreprocessorOptions& options_;
  DiagnosticEngine& diagnostics_;
  PreprocessedUnit unit_;

  std::vector<std::unique_ptr<FileState>> files_;
  std::vector<Conditional> conditionals_;
  bool skipping_ = false;
  std::unordered_map<std::string_view, std::unique_ptr<Macro>> macros_;
  std::unordered_map<std::string, FileId> loaded_files_;
  std::unordered_set<std::string> once_files_;
  Stream main_stream_{{}, true};
  bool saw_content_ = false;  // a token or non-#version directive in the main file
  bool version_applied_ = false;
  bool aborted_ = false;     // a limit was hit; wind down
  std::size_t produced_tokens_ = 0;
  SourceLocation last_location_;  // of the last token read from a file, for __LINE__
  SourceLocation directive_name_end_;  // end of the current directive's name ("#define")
  std::string_view file_name_macro_ = "__FILE__";
};

// ---------------------------------------------------------------- files ---

Token Preprocessor::get(FileState& f) {
  if (f.peeked) {
    Token t = *f.peeked;
    f.peeked.reset();
    return t;
  }
  return f.lexer.next();
}

std::vector<Token> Preprocessor::read_line(FileState& f) {
  std::vector<Token> line;
  for (;;) {
    Token t = get(f);
    if (t.at_line_start || t.kind == TokenKind::eof) {
      unget(f, t);
      return line;
    }
    line.push_back(t);
  }
}

std::uint32_t Preprocessor::line_end_offset(SourceLocation at) const {
  std::string_view line = sources_.line_text(at.file, at.line);
  return at.offset - (at.column - 1) + static_cast<std::uint32_t>(line.size());
}

void Preprocessor::record_directive(DirectiveKind kind, const Token& hash, SourceLocation last_end) {
  if (!last_end.valid() || last_end.offset < hash.range.end.offset) last_end = hash.range.end;
  SourceRange range{hash.range.begin, sources_.location_of(hash.range.begin.file, line_end_offset(last_end))};
  unit_.directives.push_back({kind, range});
}

void Preprocessor::set_skipping(bool skipping) {
  skipping_ = skipping;
  if (!files_.empty()) files_.back()->lexer.set_report_errors(!skipping);
}

void Preprocessor::note_content(const FileState& f) {
  if (f.is_command_line) return;
  if (f.is_main) saw_content_ = true;
  apply_version();
}

PPToken Preprocessor::read_file_token() {
  while (!files_.empty() && !aborted_) {
    FileState& f = *files_.back();
    Token t = get(f);
    if (t.kind == TokenKind::eof) {
      end_of_file(f);
      if (files_.size() == 1) {
        unget(f, t);
        return PPToken{t};
      }
      files_.pop_back();
      continue;
    }
    if (t.kind == TokenKind::hash && t.at_line_start) {
      handle_directive(f, t);
      // handle_directive may have pushed an include; the loop reads from it.
      while (skipping_ && !aborted_ && !files_.empty()) skip_group(*files_.back());
      continue;
    }
    note_content(f);
    last_location_ = t.range.begin;
    return PPToken{t};
  }
  Token eof;
  eof.kind = TokenKind::eof;
  return PPToken{eof};
}

void Preprocessor::end_of_file(FileState& f) {
  while (conditionals_.size() > f.conditional_base) {
    error(conditionals_.back().directive, "unterminated conditional directive");
    conditionals_.pop_back();
  }
  set_skipping(false);
}

// Reads a false group up to the #elif / #else / #endif that ends it (which is
// then handled), skipping nested conditionals.
void Preprocessor::skip_group(FileState& f) {
  std::uint32_t skip_begin = f.peeked ? f.peeked->range.begin.offset : f.lexer.offset();
  int depth = 0;
  for (;;) {
    Token t = get(f);
    if (t.kind == TokenKind::eof) {
      unget(f, t);
      if (t.range.begin.offset > skip_begin) unit_.skipped_ranges.push_back(sources_.range_of(f.file, skip_begin, t.range.begin.offset));
      end_of_file(f);  // reports the unterminated #if and stops skipping
      return;
    }
    if (t.kind != TokenKind::hash || !t.at_line_start) continue;
    Token name = get(f);
    if (name.at_line_start || name.kind == TokenKind::eof) {
      unget(f, name);
      continue;
    }
    DirectiveKind kind = directive_kind(name.text);
    if (kind == DirectiveKind::if_ || kind == DirectiveKind::ifdef || kind == DirectiveKind::ifndef) {
      ++depth;
    } else if (kind == DirectiveKind::endif && depth > 0) {
      --depth;
    } else if ((kind == DirectiveKind::elif || kind == DirectiveKind::else_ || kind == DirectiveKind::endif) &&
               depth == 0) {
      if (t.range.begin.offset > skip_begin) {
        unit_.skipped_ranges.push_back(sources_.range_of(f.file, skip_begin, t.range.begin.offset));
      }
      f.lexer.set_report_errors(true);
      directive_name_end_ = name.range.end;
      directive_elif_else_endif(f, t, kind);
      return;
    }
    read_line(f);
  }
}

void Preprocessor::handle_directive(FileState& f, const Token& hash) {
  Token name = get(f);
  if (name.at_line_start || name.kind == TokenKind::eof) {  // `#` alone: the null directive
    unget(f, name);
    record_directive(DirectiveKind::null_directive, hash, hash.range.end);
    return;
  }
  directive_name_end_ = name.range.end;
  DirectiveKind kind = name.kind == TokenKind::identifier ? directive_kind(name.text) : DirectiveKind::unknown;
  if (kind != DirectiveKind::version) note_content(f);
  switch (kind) {
    case DirectiveKind::define: return directive_define(f, hash);
    case DirectiveKind::undef: return directive_undef(f, hash);
    case DirectiveKind::if_:
    case DirectiveKind::ifdef:
    case DirectiveKind::ifndef: return directive_if(f, hash, kind);
    case DirectiveKind::elif:
    case DirectiveKind::else_:
    case DirectiveKind::endif: return directive_elif_else_endif(f, hash, kind);
    case DirectiveKind::version: return directive_version(f, hash);
    case DirectiveKind::extension: return directive_extension(f, hash);
    case DirectiveKind::pragma: return directive_pragma(f, hash);
    case DirectiveKind::line: return directive_line(f, hash);
    case DirectiveKind::error: return directive_error(f, hash, name);
    case DirectiveKind::include: return directive_include(f, hash, name);
    default: break;
  }
  std::vector<Token> rest = read_line(f);
  error(name.range, "invalid preprocessing directive '#" + std::string(name.text) + "'");
  record_directive(DirectiveKind::unknown, hash, rest.empty() ? name.range.end : rest.back().range.end);
}

void Preprocessor::extra_tokens_warning(const std::vector<Token>& line, std::size_t from, std::string_view directive) {
  if (line.size() <= from) return;
  diagnostics_.report(Diagnostic::warning(SourceRange{line[from].range.begin, line.back().range.end},
                                          "extra tokens at end of #" + std::string(directive) + " directive"));
}

bool Preprocessor::check_macro_name(const Token& name, bool defining, bool command_line) {
  if (name.kind != TokenKind::identifier) {
    error(name.range, "macro name must be an identifier");
    return false;
  }
  if (name.text == "defined") {
    error(name.range, "'defined' cannot be used as a macro name");
    return false;
  }
  if (Macro* m = find_macro(name.text); m && m->predefined) {
    error(name.range, std::string(defining ? "cannot redefine" : "cannot undefine") + " predefined macro '" +
                          std::string(name.text) + "'");
    return false;
  }
  if (command_line) return true;
  if (starts_with(name.text, "GL_")) {
    error(name.range, "macro names beginning with 'GL_' are reserved");
    return false;
  }
  if (name.text.find("__") != std::string_view::npos) {
    diagnostics_.report(Diagnostic::warning(name.range, "macro names containing '__' are reserved"));
  }
  return true;
}

// ------------------------------------------------------------ #define ---

void Preprocessor::directive_define(FileState& f, const Token& hash) {
  std::vector<Token> line = read_line(f);
  record_directive(DirectiveKind::define, hash, line.empty() ? hash.range.end : line.back().range.end);
  if (line.empty()) {
    error(directive_range(hash, line), "macro name missing in #define");
    return;
  }
  if (!check_macro_name(line[0], true, f.is_command_line)) return;
  auto macro = std::make_unique<Macro>();
  macro->name = line[0].text;
  macro->name_range = line[0].range;
  std::size_t i = 1;
  if (i < line.size() && line[i].kind == TokenKind::l_paren && !line[i].leading_space) {
    macro->function_like = true;
    ++i;
    bool closed = false;
    if (i < line.size() && line[i].kind == TokenKind::r_paren) {
      ++i;
      closed = true;
    }
    while (!closed) {
      if (i >= line.size() || line[i].kind != TokenKind::identifier) {
        error(i < line.size() ? line[i].range : line.back().range, "expected a parameter name in macro parameter list");
        return;
      }
      if (macro->param_index(line[i].text) >= 0) {
        error(line[i].range, "duplicate macro parameter '" + std::string(line[i].text) + "'");
        return;
      }
      macro->params.push_back(line[i].text);
      ++i;
      if (i < line.size() && line[i].kind == TokenKind::comma) {
        ++i;
      } else if (i < line.size() && line[i].kind == TokenKind::r_paren) {
        ++i;
        closed = true;
      } else {
        error(i < line.size() ? line[i].range : line.back().range, "expected ',' or ')' in macro parameter list");
        return;
      }
    }
  }
  macro->body.assign(line.begin() + static_cast<std::ptrdiff_t>(i), line.end());
  const auto& body = macro->body;
  if (!body.empty() && (body.front().kind == TokenKind::hash_hash || body.back().kind == TokenKind::hash_hash)) {
    const Token& bad = body.front().kind == TokenKind::hash_hash ? body.front() : body.back();
    error(bad.range, "'##' cannot appear at either end of a macro body");
    return;
  }
  for (const Token& t : body) {
    if (t.kind == TokenKind::hash) {
      diagnostics_.report(Diagnostic::error(t.range, "'#' is not allowed in a macro body")
                              .with_hint("GLSL has no stringizing operator; only '##' (token pasting) is supported"));
      return;
    }
  }
  auto it = macros_.find(macro->name);
  if (it != macros_.end()) {
    if (!it->second->same_definition(*macro)) {
      Diagnostic d = Diagnostic::error(macro->name_range, "'" + std::string(macro->name) + "' macro redefined");
      if (it->second->name_range.valid()) d.with_note(Diagnostic::note(it->second->name_range, "previous definition is here"));
      diagnostics_.report(std::move(d));
    }
    return;  // an identical redefinition changes nothing
  }
  std::string_view key = macro->name;
  macros_.emplace(key, std::move(macro));
}

void Preprocessor::directive_undef(FileState& f, const Token& hash) {
  std::vector<Token> line = read_line(f);
  record_directive(DirectiveKind::undef, hash, line.empty() ? hash.range.end : line.back().range.end);
  if (line.empty()) {
    error(directive_range(hash, line), "macro name missing in #undef");
    return;
  }
  if (!check_macro_name(line[0], false, f.is_command_line)) return;
  extra_tokens_warning(line, 1, "undef");
  macros_.erase(line[0].text);
}

// -------------------------------------------------------- conditionals ---

void Preprocessor::directive_if(FileState& f, const Token& hash, DirectiveKind kind) {
  std::vector<Token> line = read_line(f);
  record_directive(kind, hash, line.empty() ? hash.range.end : line.back().range.end);
  SourceRange directive = directive_range(hash, line);
  if (static_cast<int>(conditionals_.size()) >= options_.max_conditional_depth) {
    error(directive, "#if nested too deeply (limit " + std::to_string(options_.max_conditional_depth) + ")");
    aborted_ = true;
    return;
  }
  bool value = false;
  if (kind == DirectiveKind::if_) {
    value = evaluate_condition(line, hash);
  } else {
    std::string_view spelled = kind == DirectiveKind::ifdef ? "ifdef" : "ifndef";
    if (line.empty()) {
      error(directive, "macro name missing in #" + std::string(spelled));
    } else if (line[0].kind != TokenKind::identifier) {
      error(line[0].range, "macro name must be an identifier");
    } else {
      extra_tokens_warning(line, 1, spelled);
      value = (find_macro(line[0].text) != nullptr) == (kind == DirectiveKind::ifdef);
    }
  }
  conditionals_.push_back({directive, value, false});
  set_skipping(!value);
}

void Preprocessor::directive_elif_else_endif(FileState& f, const Token& hash, DirectiveKind kind) {
  std::vector<Token> line = read_line(f);
  record_directive(kind, hash, line.empty() ? hash.range.end : line.back().range.end);
  SourceRange directive = directive_range(hash, line);
  std::string_view spelled = kind == DirectiveKind::elif ? "elif" : kind == DirectiveKind::else_ ? "else" : "endif";
  if (conditionals_.size() <= f.conditional_base) {
    error(directive, "#" + std::string(spelled) + " without #if");
    set_skipping(false);
    return;
  }
  Conditional& c = conditionals_.back();
  if (kind == DirectiveKind::endif) {
    extra_tokens_warning(line, 0, "endif");
    conditionals_.pop_back();
    set_skipping(false);
    return;
  }
  if (c.seen_else) {
    diagnostics_.report(Diagnostic::error(directive, "#" + std::string(spelled) + " after #else")
                            .with_note(Diagnostic::note(c.directive, "the conditional started here")));
    set_skipping(true);
    return;
  }
  if (kind == DirectiveKind::else_) {
    extra_tokens_warning(line, 0, "else");
    c.seen_else = true;
    set_skipping(c.taken);
    c.taken = true;
    return;
  }
  if (c.taken) {  // an earlier group was taken: #elif is not even evaluated
    set_skipping(true);
    return;
  }
  bool value = evaluate_condition(line, hash);
  conditionals_.back().taken = value;
  set_skipping(!value);
}

bool Preprocessor::evaluate_condition(const std::vector<Token>& line, const Token& hash) {
  // `defined X` and `defined(X)` are resolved before macro expansion.
  std::vector<PPToken> resolved;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const Token& t = line[i];
    if (!(t.kind == TokenKind::identifier && t.text == "defined")) {
      resolved.push_back(PPToken{t});
      continue;
    }
    std::size_t j = i + 1;
    bool paren = j < line.size() && line[j].kind == TokenKind::l_paren;
    if (paren) ++j;
    if (j >= line.size() || line[j].kind != TokenKind::identifier) {
      error(j < line.size() ? line[j].range : t.range, "expected a macro name after 'defined'");
      return false;
    }
    bool defined = find_macro(line[j].text) != nullptr;
    if (paren) {
      if (j + 1 >= line.size() || line[j + 1].kind != TokenKind::r_paren) {
        error(line[j].range, "expected ')' after 'defined(" + std::string(line[j].text) + "'");
        return false;
      }
      ++j;
    }
    Token value = t;
    value.kind = TokenKind::int_literal;
    value.text = defined ? "1" : "0";
    value.range.end = line[j].range.end;
    resolved.push_back(PPToken{value});
    i = j;
  }
  std::vector<PPToken> expanded = expand_list(std::move(resolved), kNoExpansion, 0);
  std::vector<Token> tokens;
  tokens.reserve(expanded.size());
  for (const PPToken& t : expanded) tokens.push_back(t.token);
  SourceRange directive = directive_range(hash, line);
  detail::ExpressionContext context{unit_.es, options_.max_expansion_depth};
  auto value = detail::evaluate_expression(tokens, directive, context, diagnostics_);
  return value.value_or(0) != 0;
}

// ------------------------------------------------ version, extensions ---

void Preprocessor::directive_version(FileState& f, const Token& hash) {
  std::vector<Token> line = read_line(f);
  record_directive(DirectiveKind::version, hash, line.empty() ? hash.range.end : line.back().range.end);
  SourceRange directive = directive_range(hash, line);
  if (!f.is_main) {
    error(directive, "#version is only allowed in the main file, not in an included file");
    return;
  }
  if (unit_.version_given) {
    diagnostics_.report(Diagnostic::error(directive, "#version may appear only once")
                            .with_note(Diagnostic::note(unit_.version_range, "first #version is here")));
    return;
  }
  if (saw_content_) {
    error(directive, "#version must come first in a shader, before anything but comments and white space");
    return;
  }
  if (line.empty() || line[0].kind != TokenKind::int_literal) {
    error(line.empty() ? directive : line[0].range, "expected a version number after #version");
    return;
  }
  auto number = integer_literal_value(line[0].text);
  int version = number && *number <= 1000 ? static_cast<int>(*number) : 0;
  if (!is_known_version(version)) {
    error(line[0].range, "unknown GLSL version " + std::string(line[0].text) +
                             " (expected 100, 110 ... 150, 300, 310, 320, or 330 ... 460)");
    return;
  }
  std::string profile;
  if (line.size() > 1) {
    if (line[1].kind != TokenKind::identifier ||
        (line[1].text != "es" && line[1].text != "core" && line[1].text != "compatibility")) {
      error(line[1].range, "unknown profile '" + std::string(line[1].text) +
                               "' (expected 'core', 'compatibility' or 'es')");
      return;
    }
    profile = line[1].text;
    extra_tokens_warning(line, 2, "version");
  }
  bool es_version = version == 100 || version == 300 || version == 310 || version == 320;
  if (es_version && version != 100 && profile != "es") {
    error(directive, "#version " + std::to_string(version) + " requires the 'es' profile");
    return;
  }
  if (!es_version && profile == "es") {
    error(line[1].range, "the 'es' profile requires version 300, 310 or 320");
    return;
  }
  if (!profile.empty() && profile != "es" && version < 150) {
    error(line[1].range, "profiles are only allowed from #version 150 on");
    return;
  }
  unit_.version = version;
  unit_.profile = profile;
  unit_.es = es_version;
  unit_.version_given = true;
  unit_.version_range = directive;
  apply_version();
}

void Preprocessor::define_predefined(std::string_view name, std::string_view value, Macro::Builtin builtin) {
  if (macros_.count(name)) return;
  auto m = std::make_unique<Macro>();
  m->name = name;
  m->predefined = true;
  m->builtin = builtin;
  if (!value.empty()) {
    Token t;
    t.kind = TokenKind::int_literal;
    t.text = value;
    m->body.push_back(t);
  }
  macros_.emplace(name, std::move(m));
}

void Preprocessor::apply_version() {
  if (version_applied_) return;
  version_applied_ = true;
  unit_.keywords.version = unit_.version;
  unit_.keywords.es = unit_.es;
  define_predefined("__LINE__", "", Macro::Builtin::line);
  define_predefined("__FILE__", "", Macro::Builtin::file);
  define_predefined("__VERSION__", save(std::to_string(unit_.version)));
  if (unit_.es) {
    define_predefined("GL_ES", "1");
    define_predefined("GL_es_profile", "1");
    define_predefined("GL_FRAGMENT_PRECISION_HIGH", "1");
  } else if (unit_.version >= 150) {
    define_predefined(unit_.profile == "compatibility" ? "GL_compatibility_profile" : "GL_core_profile", "1");
  }
}

void Preprocessor::directive_extension(FileState& f, const Token& hash) {
  std::vector<Token> line = read_line(f);
  record_directive(DirectiveKind::extension, hash, line.empty() ? hash.range.end : line.back().range.end);
  SourceRange directive = directive_range(hash, line);
  if (line.empty() || line[0].kind != TokenKind::identifier) {
    error(line.empty() ? directive : line[0].range, "expected an extension name after #extension");
    return;
  }
  if (line.size() < 2 || line[1].kind != TokenKind::colon) {
    error(line.size() < 2 ? line[0].range : line[1].range, "expected ':' after the extension name");
    return;
  }
  if (line.size() < 3 || line[2].kind != TokenKind::identifier) {
    error(line.size() < 3 ? line[1].range : line[2].range,
          "expected 'require', 'enable', 'warn' or 'disable' after ':'");
    return;
  }
  std::string_view name = line[0].text;
  std::string_view behavior = line[2].text;
  if (behavior != "require" && behavior != "enable" && behavior != "warn" && behavior != "disable") {
    error(line[2].range, "unknown extension behavior '" + std::string(behavior) +
                             "' (expected 'require', 'enable', 'warn' or 'disable')");
    return;
  }
  if (name == "all" && (behavior == "require" || behavior == "enable")) {
    error(line[2].range, "'all' can only be used with 'warn' or 'disable'");
    return;
  }
  extra_tokens_warning(line, 3, "extension");
  std::uint32_t groups = extension_groups_enabled_by(name);
  if (behavior == "disable") {
    unit_.keywords.extension_groups &= ~groups;
  } else {
    unit_.keywords.extension_groups |= groups;
  }
  unit_.extensions.push_back({std::string(name), std::string(behavior), directive});
}

void Preprocessor::directive_pragma(FileState& f, const Token& hash) {
  std::vector<Token> line = read_line(f);
  record_directive(DirectiveKind::pragma, hash, line.empty() ? hash.range.end : line.back().range.end);
  SourceRange directive = directive_range(hash, line);
  std::string text;
  for (const Token& t : line) {
    if (!text.empty() && t.leading_space) text += ' ';
    text += t.text;
  }
  if (text == "once") once_files_.insert(f.path);
  unit_.pragmas.push_back({std::move(text), directive});
}

void Preprocessor::directive_line(FileState& f, const Token& hash) {
  std::vector<Token> line = read_line(f);
  SourceLocation last = line.empty() ? hash.range.end : line.back().range.end;
  record_directive(DirectiveKind::line, hash, last);
  SourceRange directive = directive_range(hash, line);
  std::vector<PPToken> raw;
  for (const Token& t : line) raw.push_back(PPToken{t});
  std::vector<PPToken> expanded = expand_list(std::move(raw), kNoExpansion, 0);
  auto number = [&](std::size_t i) -> std::optional<std::uint32_t> {
    if (i >= expanded.size() || expanded[i].token.kind != TokenKind::int_literal) return std::nullopt;
    auto v = integer_literal_value(expanded[i].token.text);
    if (!v || *v > 0x7FFFFFFF) return std::nullopt;
    return static_cast<std::uint32_t>(*v);
  };
  LineDirective result;
  result.range = directive;
  auto line_number = number(0);
  if (!line_number) {
    error(expanded.empty() ? directive : expanded[0].token.range, "expected a line number after #line");
    return;
  }
  result.line = *line_number;
  if (expanded.size() > 1) {
    const Token& second = expanded[1].token;
    if (second.kind == TokenKind::string_literal && second.text.size() >= 2) {
      result.file_name = std::string(second.text.substr(1, second.text.size() - 2));
    } else if (auto source_string = number(1)) {
      result.source_string = *source_string;
    } else {
      error(second.range, "expected a source-string number or a file name after the line number");
      return;
    }
    if (expanded.size() > 2) {
      diagnostics_.report(Diagnostic::warning(expanded[2].token.range, "extra tokens at end of #line directive"));
    }
  }
  std::uint32_t next_line = line_end_offset(last);
  std::string_view text = sources_.text(f.file);
  if (next_line < text.size() && text[next_line] == '\r') ++next_line;
  if (next_line < text.size() && text[next_line] == '\n') ++next_line;
  sources_.add_line_directive(f.file, next_line, result.line, result.file_name, result.source_string);
  unit_.line_directives.push_back(std::move(result));
}

void Preprocessor::directive_error(FileState& f, const Token& hash, const Token& name) {
  SourceRange text = f.lexer.rest_of_line();
  record_directive(DirectiveKind::error, hash, text.end);
  std::string message(sources_.text(f.file).substr(text.begin.offset, text.length()));
  diagnostics_.report(Diagnostic::error(name.range, message.empty() ? "#error" : "#error: " + message));
}

// ------------------------------------------------------------ #include ---

void Preprocessor::directive_include(FileState& f, const Token& hash, const Token& name) {
  std::optional<Token> header = f.lexer.header_name();
  std::vector<Token> line = read_line(f);
  SourceLocation last = line.empty() ? (header ? header->range.end : name.range.end) : line.back().range.end;
  record_directive(DirectiveKind::include, hash, last);
  SourceRange directive{hash.range.begin, last};
  bool angled = header.has_value();
  if (!header) {
    if (line.empty() || line[0].kind != TokenKind::string_literal || line[0].text.size() < 2 ||
        line[0].text.back() != '"') {
      error(line.empty() ? name.range : line[0].range, "expected \"FILENAME\" or <FILENAME> after #include");
      return;
    }
    header = line[0];
    line.erase(line.begin());
  }
  extra_tokens_warning(line, 0, "include");
  std::string requested(header->text.substr(1, header->text.size() - 2));
  if (requested.empty()) {
    error(header->range, "empty file name in #include");
    return;
  }
  if (static_cast<int>(files_.size()) > options_.max_include_depth) {
    error(directive, "#include nested too deeply (limit " + std::to_string(options_.max_include_depth) + ")");
    aborted_ = true;
    return;
  }
  namespace fs = std::filesystem;
  std::vector<std::string> candidates;
  if (fs::path(requested).is_absolute()) {
    candidates.push_back(requested);
  } else {
    if (!angled) candidates.push_back((fs::path(f.path).parent_path() / requested).lexically_normal().string());
    for (const std::string& dir : options_.include_paths) {
      candidates.push_back((fs::path(dir) / requested).lexically_normal().string());
    }
  }
  std::string resolved;
  std::optional<std::string> contents;
  for (const std::string& candidate : candidates) {
    if (loaded_files_.count(candidate)) {
      resolved = candidate;
      break;
    }
    contents = options_.read_file ? options_.read_file(candidate) : read_from_disk(candidate);
    if (contents) {
      resolved = candidate;
      break;
    }
  }
  if (resolved.empty()) {
    Diagnostic d = Diagnostic::error(header->range, "'" + requested + "' file not found");
    if (!candidates.empty()) {
      std::string searched;
      for (const std::string& c : candidates) searched += (searched.empty() ? "" : ", ") + c;
      d.with_hint("searched " + searched);
    }
    diagnostics_.report(std::move(d));
    return;
  }
  if (once_files_.count(resolved)) return;
  for (const auto& open : files_) {
    if (open->path == resolved && !open->is_command_line) {
      std::string chain;
      for (const auto& g : files_) {
        if (!g->is_command_line) chain += g->path + " -> ";
      }
      error(header->range, "#include cycle: " + chain + resolved);
      return;
    }
  }
  FileId id;
  if (auto it = loaded_files_.find(resolved); it != loaded_files_.end()) {
    id = sources_.add_inclusion(it->second, directive);
  } else {
    if (contents->size() > options_.max_source_bytes) {
      error(header->range, "'" + requested + "' is too large (" + std::to_string(contents->size()) +
                               " bytes; limit " + std::to_string(options_.max_source_bytes) + ")");
      return;
    }
    id = sources_.add_file(resolved, std::move(*contents));
    sources_.set_included_from(id, directive);
    loaded_files_.emplace(resolved, id);
  }
  if (unit_.includes.size() >= options_.max_include_count) {
    error(directive, "more than " + std::to_string(options_.max_include_count) + " #include directives processed");
    aborted_ = true;
    return;
  }
  unit_.includes.push_back({id, resolved, directive});
  auto state = std::make_unique<FileState>(sources_, id, diagnostics_, resolved);
  state->conditional_base = conditionals_.size();
  files_.push_back(std::move(state));
}

// ------------------------------------------------------ macro expansion ---

Macro* Preprocessor::find_macro(std::string_view name) {
  auto it = macros_.find(name);
  return it == macros_.end() ? nullptr : it->second.get();
}

bool Preprocessor::over_budget(std::size_t more) {
  produced_tokens_ += more;
  if (produced_tokens_ <= options_.max_output_tokens || aborted_) return aborted_;
  error(SourceRange{last_location_, last_location_},
        "preprocessing produces more than " + std::to_string(options_.max_output_tokens) +
            " tokens (runaway macro expansion?)");
  aborted_ = true;
  return true;
}

PPToken Preprocessor::next_unexpanded(Stream& s) {
  while (!s.buffers.empty()) {
    Buffer& b = s.buffers.back();
    if (b.pos < b.tokens.size()) return b.tokens[b.pos++];
    if (b.macro) b.macro->disabled = false;
    s.buffers.pop_back();
  }
  if (s.from_files) return read_file_token();
  PPToken eof;
  eof.token.kind = TokenKind::eof;
  return eof;
}

void Preprocessor::push_back(Stream& s, PPToken t) { s.buffers.push_back(Buffer{{std::move(t)}, 0, nullptr}); }

PPToken Preprocessor::builtin_value(const Macro& m, const PPToken& name) {
  PresumedLocation at = sources_.presumed(name.token.expansion == kNoExpansion ? name.token.range.begin : last_location_);
  PPToken value = name;
  value.token.kind = TokenKind::int_literal;
  value.token.text = save(std::to_string(m.builtin == Macro::Builtin::line ? at.line : at.source_string.value_or(0)));
  return value;
}

PPToken Preprocessor::next_expanded(Stream& s, ExpansionId default_parent, int depth) {
  for (;;) {
    PPToken t = next_unexpanded(s);
    if (t.token.kind != TokenKind::identifier || t.no_expand || aborted_) return t;
    Macro* m = find_macro(t.token.text);
    if (!m) return t;
    if (m->disabled) {
      t.no_expand = true;
      return t;
    }
    if (m->builtin != Macro::Builtin::none) return builtin_value(*m, t);
    if (!expand_macro(s, *m, t, default_parent, depth)) return t;
  }
}

// Replaces the macro invocation starting at `name` by its expansion, pushed
// onto `s`. Returns false when `name` is not an invocation after all (a
// function-like macro without '(') or a limit stops it.
bool Preprocessor::expand_macro(Stream& s, Macro& m, const PPToken& name, ExpansionId default_parent, int depth) {
  std::vector<std::vector<PPToken>> args;
  SourceRange site = name.token.range;
  if (m.function_like) {
    PPToken open = next_unexpanded(s);
    if (open.token.kind != TokenKind::l_paren) {
      push_back(s, open);
      return false;
    }
    args.emplace_back();
    int parens = 0;
    for (;;) {
      PPToken t = next_unexpanded(s);
      if (t.token.kind == TokenKind::eof) {
        error(name.token.range, "unterminated argument list invoking macro '" + std::string(m.name) + "'");
        push_back(s, t);
        return false;
      }
      if (aborted_) return false;
      if (t.token.kind == TokenKind::r_paren && parens == 0) {
        if (t.token.range.begin.file == site.begin.file && t.token.expansion == name.token.expansion) {
          site.end = t.token.range.end;
        }
        break;
      }
      if (t.token.kind == TokenKind::l_paren) ++parens;
      if (t.token.kind == TokenKind::r_paren) --parens;
      if (t.token.kind == TokenKind::comma && parens == 0) {
        args.emplace_back();
        continue;
      }
      args.back().push_back(t);
    }
    if (m.params.empty() && args.size() == 1 && args[0].empty()) args.clear();
    if (args.size() != m.params.size()) {
      error(SourceRange{name.token.range.begin, site.end},
            "macro '" + std::string(m.name) + "' expects " + std::to_string(m.params.size()) + " argument" +
                (m.params.size() == 1 ? "" : "s") + ", but " + std::to_string(args.size()) +
                (args.size() == 1 ? " was" : " were") + " given");
      return true;  // the invocation is consumed; nothing replaces it
    }
  }
  int live = 0;
  for (const Buffer& b : s.buffers) live += b.macro != nullptr;
  if (depth + live >= options_.max_expansion_depth) {
    error(name.token.range, "macro expansion nested too deeply (limit " +
                                std::to_string(options_.max_expansion_depth) + ") while expanding '" +
                                std::string(m.name) + "'");
    aborted_ = true;
    return false;
  }

  ExpansionId parent = name.token.expansion != kNoExpansion ? name.token.expansion : default_parent;
  ExpansionId id = sources_.add_expansion({m.name, m.name_range, site, parent});

  std::vector<std::vector<PPToken>> expanded_args(args.size());
  for (std::size_t i = 0; i < args.size(); ++i) {
    bool needed = false;
    for (std::size_t j = 0; j < m.body.size(); ++j) {
      if (m.body[j].kind != TokenKind::identifier || m.param_index(m.body[j].text) != static_cast<int>(i)) continue;
      bool pasted = (j > 0 && m.body[j - 1].kind == TokenKind::hash_hash) ||
                    (j + 1 < m.body.size() && m.body[j + 1].kind == TokenKind::hash_hash);
      if (!pasted) needed = true;
    }
    if (needed) expanded_args[i] = expand_list(args[i], id, depth + live + 1);
    if (aborted_) return false;
  }

  std::vector<PPToken> out;
  bool paste_next = false;
  bool last_piece_empty = false;
  const Token* paste_op = nullptr;
  for (std::size_t j = 0; j < m.body.size(); ++j) {
    const Token& b = m.body[j];
    if (b.kind == TokenKind::hash_hash) {
      paste_next = true;
      paste_op = &b;
      continue;
    }
    std::vector<PPToken> piece;
    int param = b.kind == TokenKind::identifier ? m.param_index(b.text) : -1;
    if (param >= 0) {
      bool raw = paste_next || (j + 1 < m.body.size() && m.body[j + 1].kind == TokenKind::hash_hash);
      piece = raw ? args[static_cast<std::size_t>(param)] : expanded_args[static_cast<std::size_t>(param)];
      for (PPToken& t : piece) {
        if (t.token.expansion == kNoExpansion || t.token.expansion < id) t.token.expansion = id;
        t.token.at_line_start = false;
      }
      if (!piece.empty()) piece.front().token.leading_space = b.leading_space;
    } else {
      PPToken t{b};
      t.token.expansion = id;
      if (!t.token.range.valid()) t.token.range = name.token.range;  // predefined macros
      piece.push_back(t);
    }
    if (over_budget(piece.size())) return false;
    bool piece_was_empty = piece.empty();
    if (paste_next && !last_piece_empty && !piece.empty() && !out.empty()) {
      std::optional<PPToken> joined = paste(out.back(), piece.front(), *paste_op);
      if (joined) out.back() = *joined;
      piece.erase(piece.begin());
    } else if (paste_next && piece.empty()) {
      paste_next = false;
      continue;  // pasting with an empty argument leaves the left side as it is
    }
    paste_next = false;
    last_piece_empty = piece_was_empty;
    out.insert(out.end(), piece.begin(), piece.end());
  }
  if (!out.empty()) {
    out.front().token.at_line_start = name.token.at_line_start;
    out.front().token.leading_space = name.token.leading_space;
  }
  m.disabled = true;
  s.buffers.push_back(Buffer{std::move(out), 0, &m});
  return true;
}

std::optional<PPToken> Preprocessor::paste(const PPToken& lhs, const PPToken& rhs, const Token& op) {
  std::string joined = std::string(lhs.token.text) + std::string(rhs.token.text);
  FileId scratch = sources_.add_file("<paste>", joined);
  DiagnosticEngine quiet;
  Lexer lexer(sources_, scratch, quiet, LexerOptions{KeywordContext{}, false});
  Token first = lexer.next();
  Token second = lexer.next();
  if (first.kind == TokenKind::invalid || second.kind != TokenKind::eof || quiet.has_errors() ||
      first.range.length() != joined.size()) {
    diagnostics_.report(Diagnostic::error(op.range, "pasting '" + std::string(lhs.token.text) + "' and '" +
                                                        std::string(rhs.token.text) +
                                                        "' does not give a valid token")
                            .with_expansion(lhs.token.expansion));
    return std::nullopt;
  }
  PPToken result = lhs;
  result.token.kind = first.kind;
  result.token.text = first.text;  // stable: the scratch file lives in the SourceManager
  result.no_expand = false;
  return result;
}

std::vector<PPToken> Preprocessor::expand_list(std::vector<PPToken> tokens, ExpansionId default_parent, int depth) {
  if (depth >= options_.max_expansion_depth) {
    if (!aborted_) {
      error(tokens.empty() ? SourceRange{last_location_, last_location_} : tokens.front().token.range,
            "macro arguments nested too deeply (limit " + std::to_string(options_.max_expansion_depth) + ")");
    }
    aborted_ = true;
    return {};
  }
  Stream list;
  list.buffers.push_back(Buffer{std::move(tokens), 0, nullptr});
  std::vector<PPToken> out;
  for (;;) {
    PPToken t = next_expanded(list, default_parent, depth);
    if (t.token.kind == TokenKind::eof || aborted_) break;
    out.push_back(t);
  }
  // Macros whose expansions were cut short by the end of the list are live again.
  for (Buffer& b : list.buffers) {
    if (b.macro) b.macro->disabled = false;
  }
  return out;
}

// --------------------------------------------------------------- output ---

void Preprocessor::emit(const PPToken& t) {
  Token token = t.token;
  switch (token.kind) {
    case TokenKind::invalid: return;  // already reported by the lexer
    case TokenKind::identifier: token.kind = classify_word(token.text, unit_.keywords); break;
    case TokenKind::hash:
    case TokenKind::hash_hash:
      diagnostics_.report(Diagnostic::error(token.range, "'" + std::string(token.text) +
                                                             "' is only allowed at the start of a directive line")
                              .with_expansion(token.expansion));
      return;
    case TokenKind::string_literal:
      diagnostics_.report(
          Diagnostic::error(token.range, "string literals are not allowed in GLSL").with_expansion(token.expansion));
      return;
    default: break;
  }
  if (unit_.tokens.size() >= options_.max_output_tokens) {
    over_budget(options_.max_output_tokens + 1);
    return;
  }
  unit_.tokens.push_back(token);
}

PreprocessedUnit Preprocessor::run(FileId main_file) {
  std::string_view text = sources_.text(main_file);
  Token end;
  end.kind = TokenKind::eof;
  end.at_line_start = true;
  end.range = sources_.range_of(main_file, static_cast<std::uint32_t>(text.size()),
                                static_cast<std::uint32_t>(text.size()));
  if (text.size() > options_.max_source_bytes) {
    error(sources_.range_of(main_file, 0, 0), "the shader is too large (" + std::to_string(text.size()) +
                                                  " bytes; limit " + std::to_string(options_.max_source_bytes) + ")");
    unit_.tokens.push_back(end);
    return std::move(unit_);
  }
  auto main_state = std::make_unique<FileState>(sources_, main_file, diagnostics_, sources_.path(main_file));
  main_state->is_main = true;
  files_.push_back(std::move(main_state));
  loaded_files_.emplace(sources_.path(main_file), main_file);

  if (!options_.defines.empty() || !options_.undefines.empty()) {
    std::string prelude;
    for (const auto& [name, value] : options_.defines) prelude += "#define " + name + " " + value + "\n";
    for (const std::string& name : options_.undefines) prelude += "#undef " + name + "\n";
    FileId id = sources_.add_file("<command line>", std::move(prelude));
    auto state = std::make_unique<FileState>(sources_, id, diagnostics_, "<command line>");
    state->is_command_line = true;
    files_.push_back(std::move(state));
  }

  for (;;) {
    PPToken t = next_expanded(main_stream_, kNoExpansion, 0);
    if (t.token.kind == TokenKind::eof || aborted_ || diagnostics_.limit_reached()) break;
    emit(t);
  }
  apply_version();
  unit_.tokens.push_back(end);
  return std::move(unit_);
}

}  // namespace

PreprocessedUnit preprocess(SourceManager& sources, FileId main_file, const PreprocessorOptions& options,
                            DiagnosticEngine& diagnostics) {
  return Preprocessor(sources, options, diagnostics).run(main_file);
}

}  // namespace safegi
