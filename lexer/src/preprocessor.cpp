#include <safegi/lexer/preprocessor.hpp>

#include <algorithm>
#include <string>

#include <safegi/diagnostics/codes.hpp>

#include "preprocessor_impl.hpp"

namespace safegi {
namespace detail {
namespace {

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


}  // namespace

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
  if (f.peeked) {
    if (f.peeked->at_line_start || f.peeked->kind == TokenKind::eof) return line;
    line.push_back(*f.peeked);
    f.peeked.reset();
  }
  // The token after the line is not lexed here: whether its errors are
  // reported depends on what this directive decides (a false #if skips it).
  while (!f.lexer.next_starts_line()) line.push_back(f.lexer.next());
  return line;
}

std::vector<Token> Preprocessor::read_directive_line(FileState& f, DirectiveKind kind, const Token& hash) {
  std::vector<Token> line = read_line(f);
  record_directive(kind, hash, line.empty() ? directive_name_end_ : line.back().range.end);
  return line;
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
    error(code::E_CONDITIONAL, conditionals_.back().directive, "unterminated conditional directive");
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
    if (!f.peeked) f.lexer.skip_to_directive_line();
    Token t = get(f);
    if (t.kind == TokenKind::eof) {
      unget(f, t);
      if (t.range.begin.offset > skip_begin) unit_.skipped_ranges.push_back(sources_.range_of(f.file, skip_begin, t.range.begin.offset));
      end_of_file(f);  // reports the unterminated #if and stops skipping
      return;
    }
    if (t.kind != TokenKind::hash || !t.at_line_start) continue;
    if (f.lexer.next_starts_line()) continue;
    Token name = get(f);
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
  if (f.lexer.next_starts_line()) {  // `#` alone: the null directive
    record_directive(DirectiveKind::null_directive, hash, hash.range.end);
    return;
  }
  Token name = get(f);
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
  error(code::E_DIRECTIVE, name.range, "invalid preprocessing directive '#" + std::string(name.text) + "'");
  record_directive(DirectiveKind::unknown, hash, rest.empty() ? name.range.end : rest.back().range.end);
}

void Preprocessor::extra_tokens_warning(const std::vector<Token>& line, std::size_t from, std::string_view directive) {
  if (line.size() <= from) return;
  diagnostics_.report(Diagnostic::warning(SourceRange{line[from].range.begin, line.back().range.end},
                                          "extra tokens at end of #" + std::string(directive) + " directive")
                          .with_code(code::W_EXTRA_TOKENS));
}

bool Preprocessor::check_macro_name(const Token& name, bool defining, bool command_line) {
  if (name.kind != TokenKind::identifier) {
    error(code::E_MACRO, name.range, "macro name must be an identifier");
    return false;
  }
  if (name.text == "defined") {
    error(code::E_MACRO, name.range, "'defined' cannot be used as a macro name");
    return false;
  }
  // GL_EXT_spirv_intrinsics lets a shader define `GL_` macros (glslang's reservedPpErrorCheck), as
  // its shaders do to say which extension's built-ins they declare themselves; an extension's own
  // macro then follows the rule of any macro (the same definition again is no redefinition).
  const bool spirv_intrinsics = unit_.language.extension_enabled("GL_EXT_spirv_intrinsics");
  if (Macro* m = find_macro(name.text); m && m->predefined && !(spirv_intrinsics && name.text.starts_with("GL_"))) {
    error(code::E_MACRO, name.range,
          std::string(defining ? "cannot redefine" : "cannot undefine") + " predefined macro '" +
              std::string(name.text) + "'");
    return false;
  }
  if (command_line) return true;
  if (name.text.starts_with("GL_") && !spirv_intrinsics) {
    error(code::E_MACRO, name.range, "macro names beginning with 'GL_' are reserved");
    return false;
  }
  if (name.text.find("__") != std::string_view::npos && !spirv_intrinsics) {
    diagnostics_.report(
        Diagnostic::warning(name.range, "macro names containing '__' are reserved").with_code(code::W_MACRO));
  }
  return true;
}

// -------------------------------------------------------- conditionals ---

void Preprocessor::directive_if(FileState& f, const Token& hash, DirectiveKind kind) {
  std::vector<Token> line = read_directive_line(f, kind, hash);
  SourceRange directive = directive_range(hash, line);
  if (static_cast<int>(conditionals_.size()) >= options_.max_conditional_depth) {
    error(code::E_LIMIT, directive,
          "#if nested too deeply (limit " + std::to_string(options_.max_conditional_depth) + ")");
    aborted_ = true;
    return;
  }
  bool value = false;
  if (kind == DirectiveKind::if_) {
    value = evaluate_condition(line, hash);
  } else {
    std::string_view spelled = kind == DirectiveKind::ifdef ? "ifdef" : "ifndef";
    if (line.empty()) {
      error(code::E_DIRECTIVE, directive, "macro name missing in #" + std::string(spelled));
    } else if (line[0].kind != TokenKind::identifier) {
      error(code::E_MACRO, line[0].range, "macro name must be an identifier");
    } else {
      extra_tokens_warning(line, 1, spelled);
      value = (find_macro(line[0].text) != nullptr) == (kind == DirectiveKind::ifdef);
    }
  }
  conditionals_.push_back({directive, value, false});
  set_skipping(!value);
}

void Preprocessor::directive_elif_else_endif(FileState& f, const Token& hash, DirectiveKind kind) {
  std::vector<Token> line = read_directive_line(f, kind, hash);
  SourceRange directive = directive_range(hash, line);
  std::string_view spelled = kind == DirectiveKind::elif ? "elif" : kind == DirectiveKind::else_ ? "else" : "endif";
  if (conditionals_.size() <= f.conditional_base) {
    error(code::E_CONDITIONAL, directive, "#" + std::string(spelled) + " without #if");
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
                            .with_code(code::E_CONDITIONAL)
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
      error(code::E_PP_EXPRESSION, j < line.size() ? line[j].range : t.range, "expected a macro name after 'defined'");
      return false;
    }
    bool defined = find_macro(line[j].text) != nullptr;
    if (paren) {
      if (j + 1 >= line.size() || line[j + 1].kind != TokenKind::r_paren) {
        error(code::E_PP_EXPRESSION, line[j].range, "expected ')' after 'defined(" + std::string(line[j].text) + "'");
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

// --------------------------------------------------------------- output ---

void Preprocessor::emit(const PPToken& t) {
  Token token = t.token;
  switch (token.kind) {
    case TokenKind::invalid:
      diagnostics_.report(Diagnostic::error(token.range, invalid_character_message(token.text))
                              .with_code(code::E_CHARACTER)
                              .with_expansion(token.expansion));
      return;
    case TokenKind::identifier: token.kind = classify_word(token.text, unit_.keywords); break;
    case TokenKind::hash:
    case TokenKind::hash_hash:
      diagnostics_.report(Diagnostic::error(token.range, "'" + std::string(token.text) +
                                                             "' is only allowed at the start of a directive line")
                              .with_code(code::E_CHARACTER)
                              .with_expansion(token.expansion));
      return;
    case TokenKind::int_literal:
    case TokenKind::uint_literal:
    case TokenKind::int64_literal:
    case TokenKind::uint64_literal:
    case TokenKind::int16_literal:
    case TokenKind::uint16_literal:
    case TokenKind::float_literal:
    case TokenKind::double_literal:
    case TokenKind::float16_literal:
      if (NumericLiteralCheck check = check_numeric_literal(token.text); !check.error.empty()) {
        SourceRange range = token.range;
        if (range.length() == token.text.size() && range.begin.line == range.end.line) {
          range.begin.offset += check.error_begin;
          range.begin.column += check.error_begin;
          range.end = range.begin;
          range.end.offset += check.error_end - check.error_begin;
          range.end.column += check.error_end - check.error_begin;
        }
        diagnostics_.report(Diagnostic::error(range, std::move(check.error))
                                .with_code(code::E_LITERAL)
                                .with_expansion(token.expansion));
      } else if (check.kind == TokenKind::double_literal && !unit_.language.allows(LanguageFeature::double_literals)) {
        diagnostics_.report(
            Diagnostic::error(token.range, feature_requirement(LanguageFeature::double_literals, unit_.es))
                .with_code(code::E_VERSION)
                .with_expansion(token.expansion));
      }
      break;
    case TokenKind::string_literal:
      if (strings_allowed_) break;  // GL_EXT_debug_printf
      diagnostics_.report(Diagnostic::error(token.range, "string literals are not allowed in GLSL")
                              .with_code(code::E_CHARACTER)
                              .with_expansion(token.expansion));
      return;
    default: break;
  }
  if (unit_.tokens.size() >= options_.max_output_tokens) {
    over_budget(options_.max_output_tokens + 1);
    return;
  }
  if (token.kind == TokenKind::kw_int && !unit_.tokens.empty() && unit_.keywords.enabled(ExtensionGroup::unsigned_integers)) {
    Token& previous = unit_.tokens.back();
    if (previous.kind == TokenKind::reserved_word && previous.text == "unsigned" &&
        previous.range.begin.file == token.range.begin.file) {
      // GL_EXT_gpu_shader4 spells uint `unsigned int`: one token, printed `uint`.
      previous.kind = TokenKind::kw_uint;
      previous.text = "uint";
      previous.range.end = token.range.end;
      return;
    }
  }
  unit_.tokens.push_back(token);
}

bool Preprocessor::refuse_non_text(FileId file) {
  // Looks at the start only: text has no NUL byte, and few control characters besides tab,
  // newline, vertical tab, form feed and carriage return.
  constexpr std::size_t kSniffed = 4096, kMostControls = kSniffed / 32;
  const std::string_view text = sources_.text(file).substr(0, kSniffed);
  const auto refuse = [&](std::size_t at, std::string message, std::string hint) {
    const auto offset = static_cast<std::uint32_t>(at);
    diagnostics_.report(Diagnostic::error(sources_.range_of(file, offset, offset + 1), std::move(message))
                            .with_code(code::E_NOT_TEXT)
                            .with_hint(std::move(hint)));
    return true;
  };
  std::size_t controls = 0, first_control = text.size();
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte == 0) {
      return refuse(i, "the file is not text: it holds a NUL byte",
                    "a shader is text: is this the right file (not an image, an object file or UTF-16)?");
    }
    if ((byte < 0x20 && byte != '\t' && byte != '\n' && byte != '\v' && byte != '\f' && byte != '\r') || byte == 0x7F) {
      ++controls;
      first_control = std::min(first_control, i);
    }
  }
  if (controls <= kMostControls) return false;
  return refuse(first_control,
                "the file is not text: " + std::to_string(controls) + " of its first " + std::to_string(text.size()) +
                    " bytes are control characters",
                "a shader is text: is this the right file?");
}

PreprocessedUnit Preprocessor::run(FileId main_file) {
  const bool overridden = options_.override_version != 0;
  unit_.version = overridden ? options_.override_version : options_.default_version;
  unit_.es = overridden ? options_.override_es : options_.default_es;
  unit_.profile = unit_.es && unit_.version != 100 ? "es" : "";
  std::string_view text = sources_.text(main_file);
  Token end;
  end.kind = TokenKind::eof;
  end.at_line_start = true;
  end.range = sources_.range_of(main_file, static_cast<std::uint32_t>(text.size()),
                                static_cast<std::uint32_t>(text.size()));
  if (text.size() > options_.max_source_bytes) {
    error(code::E_LIMIT, sources_.range_of(main_file, 0, 0),
          "the shader is too large (" + std::to_string(text.size()) + " bytes; limit " +
              std::to_string(options_.max_source_bytes) + ")");
    unit_.tokens.push_back(end);
    return std::move(unit_);
  }
  if (refuse_non_text(main_file)) {
    unit_.tokens.push_back(end);
    return std::move(unit_);
  }
  unit_.tokens.reserve(text.size() / 5);
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

}  // namespace detail

PreprocessedUnit preprocess(SourceManager& sources, FileId main_file, const PreprocessorOptions& options,
                            DiagnosticEngine& diagnostics) {
  return detail::Preprocessor(sources, options, diagnostics).run(main_file);
}

}  // namespace safegi
