// Macro replacement: invocations, argument pre-expansion, substitution,
// token pasting, and the limits that keep runaway expansions finite.

#include <algorithm>
#include <string>

#include "preprocessor_impl.hpp"

namespace safegi::detail {

// ------------------------------------------------------ macro expansion ---

Macro* Preprocessor::find_macro(std::string_view name) {
  const auto initial = name.empty() ? 0u : static_cast<unsigned char>(name[0]);
  if (!((macro_initials_[initial >> 6] >> (initial & 63u)) & 1u) ||
      !((macro_lengths_ >> std::min<std::size_t>(name.size(), 63)) & 1u))
    return nullptr;
  auto it = macros_.find(name);
  return it == macros_.end() ? nullptr : it->second.get();
}

bool Preprocessor::over_budget(std::size_t more) {
  produced_tokens_ += more;
  if (produced_tokens_ <= options_.max_output_tokens || aborted_) return aborted_;
  error(code::E_LIMIT, SourceRange{last_location_, last_location_},
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
  PPToken value = name;
  value.token.kind = TokenKind::int_literal;
  if (m.builtin == Macro::Builtin::line) {
    PresumedLocation at =
        sources_.presumed(name.token.expansion == kNoExpansion ? name.token.range.begin : last_location_);
    value.token.text = save(std::to_string(at.line));
    return value;
  }
  const FileState* file = files_.empty() ? nullptr : files_.back().get();
  if (file && !file->line_file_name.empty()) {
    value.token.kind = TokenKind::string_literal;
    value.token.text = save("\"" + std::string(file->line_file_name) + "\"");
    return value;
  }
  value.token.text = save(std::to_string(file ? file->source_string : 0));
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
        error(code::E_MACRO, name.token.range,
              "unterminated argument list invoking macro '" + std::string(m.name) + "'");
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
      error(code::E_MACRO, SourceRange{name.token.range.begin, site.end},
            "macro '" + std::string(m.name) + "' expects " + std::to_string(m.params.size()) + " argument" +
                (m.params.size() == 1 ? "" : "s") + ", but " + std::to_string(args.size()) +
                (args.size() == 1 ? " was" : " were") + " given");
      return true;  // the invocation is consumed; nothing replaces it
    }
  }
  if (m.paste_at_edge.valid()) {
    diagnostics_.report(
        Diagnostic::error(SourceRange{name.token.range.begin, site.end},
                          "macro '" + std::string(m.name) + "' cannot be used: '##' at an end of its body")
            .with_code(code::E_MACRO)
            .with_note(Diagnostic::note(m.paste_at_edge, "'##' is here"))
            .with_expansion(name.token.expansion));
    return true;  // the invocation is consumed; nothing replaces it
  }
  int live = 0;
  for (const Buffer& b : s.buffers) live += b.macro != nullptr;
  if (depth + live >= options_.max_expansion_depth) {
    error(code::E_LIMIT, name.token.range,
          "macro expansion nested too deeply (limit " + std::to_string(options_.max_expansion_depth) +
              ") while expanding '" + std::string(m.name) + "'");
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
  Lexer lexer(sources_, scratch, quiet, LexerOptions{KeywordContext{}, false, false, false});
  Token first = lexer.next();
  Token second = lexer.next();
  if (first.kind == TokenKind::invalid || second.kind != TokenKind::eof || quiet.has_errors() ||
      first.range.length() != joined.size()) {
    diagnostics_.report(Diagnostic::error(op.range, "pasting '" + std::string(lhs.token.text) + "' and '" +
                                                        std::string(rhs.token.text) + "' does not give a valid token")
                            .with_code(code::E_MACRO)
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
      error(code::E_LIMIT, tokens.empty() ? SourceRange{last_location_, last_location_} : tokens.front().token.range,
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

}  // namespace safegi::detail
