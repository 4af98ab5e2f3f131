// GL_EXT_spirv_intrinsics (docs/safeglslc.md, "SPIR-V intrinsics"): the qualifiers
// spirv_decorate, spirv_decorate_id, spirv_decorate_string, spirv_storage_class,
// spirv_execution_mode(_id), spirv_instruction, spirv_by_reference and spirv_literal, and
// the type specifier spirv_type. The words are keywords only with the extension (as in
// glslang); without it, a word used as one (followed by its argument list, or by a type) is
// parsed as one and reported as needing the extension. Each argument list is checked against
// glslang's grammar for the word: requirements (`extensions = [...]`, `capabilities = [...]`)
// first, then the word's own arguments.

#include <algorithm>
#include <array>

#include "parser_impl.hpp"

namespace safegi::parser_detail {

using namespace ast;

namespace {

constexpr std::string_view kExtension = "GL_EXT_spirv_intrinsics";

// The words that take an argument list.
constexpr std::array<std::string_view, 8> kListWords = {
    "spirv_decorate",       "spirv_decorate_id",       "spirv_decorate_string", "spirv_storage_class",
    "spirv_execution_mode", "spirv_execution_mode_id", "spirv_instruction",     "spirv_type"};

bool word_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.';
}

bool is_int_literal(const Expr* e) {
  const auto* lit = dyn_cast<LiteralExpr>(e);
  return lit && lit->literal_kind == LiteralKind::Int;
}

bool is_literal(const Expr* e, bool strings) {
  const auto* lit = dyn_cast<LiteralExpr>(e);
  return lit && lit->literal_kind != LiteralKind::Double && (strings || lit->literal_kind != LiteralKind::String);
}

}  // namespace

bool Parser::spirv_enabled() const {
  return !options_.language || options_.language->extension_enabled(kExtension);
}

bool Parser::at_spirv_qualifier() const {
  const PToken& t = peek();
  if (t.kind != T::Ident || t.text.substr(0, 6) != "spirv_" || lookup(t.text) != nullptr) return false;
  if (t.text == "spirv_by_reference" || t.text == "spirv_literal") {
    if (spirv_enabled()) return true;
    const PToken& next = peek(1);  // without the extension: only where a parameter's type follows
    return next.kind == T::TypeKw || next.kind == T::QualKw || (next.kind == T::Ident && is_type_name(next.text));
  }
  if (t.text == "spirv_type") return false;
  return peek(1).kind == T::LParen &&
         std::find(kListWords.begin(), kListWords.end(), t.text) != kListWords.end();
}

bool Parser::at_spirv_type() const {
  const PToken& t = peek();
  return t.kind == T::Ident && t.text == "spirv_type" && peek(1).kind == T::LParen && lookup(t.text) == nullptr;
}

void Parser::require_spirv(const PToken& word) {
  if (spirv_enabled()) return;
  diagnostics_.report(Diagnostic::error(word.range, "'" + std::string(word.text) + "' requires " + std::string(kExtension))
                          .with_code(code::E_VERSION)
                          .with_hint("enable it with '#extension " + std::string(kExtension) + " : enable'"));
}

Qualifier Parser::parse_spirv_qualifier() {
  Qualifier q;
  q.kind = QualifierKind::Spirv;
  q.word = std::string(peek().text);
  SourceLocation begin = here();
  const std::size_t first = pos_;
  require_spirv(peek());
  advance();
  if (q.word != "spirv_by_reference" && q.word != "spirv_literal") q.spirv_args = parse_spirv_args(q.word);
  q.range = range_from(begin);
  q.spirv_text = spirv_spelling(first);
  return q;
}

TypeSpecifier* Parser::parse_spirv_type() {
  SourceLocation begin = here();
  auto* type = make<TypeSpecifier>(begin);
  type->form = TypeSpecifier::Form::Spirv;
  const std::size_t first = pos_;
  require_spirv(peek());
  type->name_range = advance().range;
  type->spirv_args = parse_spirv_args("spirv_type");
  type->name = spirv_spelling(first);
  type->range = range_from(begin);
  return type;
}

std::string Parser::spirv_spelling(std::size_t first) const {
  std::string text;
  for (std::size_t i = first; i < pos_ && i < tokens_.size(); ++i) {
    const std::string_view t = tokens_[i].text;
    if (!text.empty() && !t.empty() && word_char(text.back()) && word_char(t.front())) text += ' ';
    text += t;
    if (tokens_[i].kind == T::Comma) text += ' ';
  }
  return text;
}

// `( requirements..., arguments... )`, checked against the word's grammar (glslang.y).
std::vector<SpirvArg> Parser::parse_spirv_args(std::string_view word) {
  DepthGuard guard(*this);
  const std::string context = "in '" + std::string(word) + "(...)'";
  expect(T::LParen, "'('", "after '" + std::string(word) + "'");
  std::vector<SpirvArg> args;
  const bool is_type = word == "spirv_type";
  const bool is_instruction = word == "spirv_instruction";
  bool past_requirements = false;
  bool past_ids = false;  // spirv_instruction and spirv_type: after `set = ` / `id = `
  bool has_id = false;
  std::size_t positional = 0;  // arguments after the requirements (and ids)
  const std::string first_expected =
      is_type || is_instruction               ? "'id = ...'"
      : word == "spirv_storage_class"         ? "an integer literal (a storage class)"
      : word.substr(0, 20) == "spirv_execution_mode" ? "an integer literal (an execution mode)"
                                              : "an integer literal (a decoration)";
  if (at(T::RParen)) fail_expected(first_expected, context);
  do {
    SpirvArg arg;
    SourceLocation begin = here();
    const PToken& first = peek();
    if (at(T::Ident) && peek(1).kind == T::Assign) {
      const std::string_view name = first.text;
      if (name == "extensions" || name == "capabilities") {
        if (past_requirements) fail_expected("'extensions = [...]' and 'capabilities = [...]' first", context);
        arg.kind = name == "extensions" ? SpirvArg::Kind::Extensions : SpirvArg::Kind::Capabilities;
        advance();
        advance();
        expect(T::LBracket, "'['", "after '" + std::string(name) + " ='");
        do {
          if (arg.kind == SpirvArg::Kind::Extensions) {
            if (!at(T::StringLit)) fail_expected("a string literal (an extension's name)", context);
          } else if (!at(T::IntLit)) {
            fail_expected("an integer literal (a capability)", context);
          }
          arg.list.push_back(make_literal(advance()));
        } while (accept(T::Comma));
        expect(T::RBracket, "']'", "to close the list " + context);
      } else if ((name == "set" || name == "id") && (is_type || is_instruction)) {
        if (past_ids) fail_expected("'set = ' and 'id = ' before the type's parameters", context);
        past_requirements = true;
        arg.kind = name == "set" ? SpirvArg::Kind::Set : SpirvArg::Kind::Id;
        has_id = has_id || name == "id";
        advance();
        advance();
        if (name == "set" ? !at(T::StringLit) : !at(T::IntLit))
          fail_expected(name == "set" ? "a string literal (an instruction set's name)" : "an integer literal (an opcode)",
                        context);
        arg.value = make_literal(advance());
      } else {
        fail(code::E_SYNTAX, first.range,
             "unknown argument '" + std::string(name) + "' " + context + ": expected " +
                 (is_type || is_instruction ? "extensions, capabilities, set or id" : "extensions or capabilities"));
      }
    } else {
      past_requirements = true;
      if (is_instruction || (is_type && !has_id)) {
        fail_expected(has_id || !is_type ? "'set = \"...\"' or 'id = ...'" : "'id = ...' (the type's opcode)", context);
      }
      if (is_type) past_ids = true;
      if (is_type && (at(T::TypeKw) || (at(T::Ident) && is_type_name(first.text) &&
                                        (peek(1).kind == T::Comma || peek(1).kind == T::RParen)))) {
        arg.kind = SpirvArg::Kind::Type;
        arg.type = parse_type_specifier_nonarray();
      } else {
        arg.kind = SpirvArg::Kind::Value;
        arg.value = parse_conditional();
        check_spirv_value(word, positional, first, arg.value, context);
      }
      ++positional;
    }
    arg.range = range_from(begin);
    args.push_back(std::move(arg));
  } while (accept(T::Comma));
  if (!at(T::RParen)) fail_expected("',' or ')'", context);
  const bool one_more = word == "spirv_execution_mode_id" || word == "spirv_decorate_id" || word == "spirv_decorate_string";
  if ((is_type || is_instruction) ? !has_id : positional == 0) {
    fail_expected(first_expected, context);
  } else if (one_more && positional == 1) {
    fail_expected(word == "spirv_decorate_string" ? "',' and a string literal" : "',' and an operand", context);
  }
  advance();
  return args;
}

// A positional argument: the first of a decoration, storage class or execution mode is an integer
// literal (its number); the rest are literals (spirv_decorate, spirv_execution_mode), string literals
// (spirv_decorate_string), a constant or a variable's name (spirv_decorate_id) or constant
// expressions (spirv_execution_mode_id, spirv_type).
void Parser::check_spirv_value(std::string_view word, std::size_t index, const PToken& first, const Expr* value,
                               const std::string& context) {
  auto wrong = [&](std::string_view what) {
    fail(code::E_SYNTAX, value->range, "expected " + std::string(what) + " " + context + ", found " + describe(first));
  };
  if (word == "spirv_type") return;  // constant expressions (the checker's)
  if (index == 0) {
    if (!is_int_literal(value)) {
      wrong(word == "spirv_storage_class"                    ? "an integer literal (a storage class)"
            : word.substr(0, 20) == "spirv_execution_mode" ? "an integer literal (an execution mode)"
                                                           : "an integer literal (a decoration)");
    }
    return;
  }
  if (word == "spirv_storage_class") wrong("')' after the storage class");
  if (word == "spirv_decorate" && !is_literal(value, false)) wrong("a literal (int, uint, float or bool)");
  if (word == "spirv_execution_mode" && !is_literal(value, true)) wrong("a literal (int, uint, float, bool or string)");
  if (word == "spirv_decorate_string" && !(dyn_cast<LiteralExpr>(value) &&
                                           dyn_cast<LiteralExpr>(value)->literal_kind == LiteralKind::String))
    wrong("a string literal");
  if (word == "spirv_decorate_id" && !is_literal(value, false) && value->kind != NodeKind::IdentifierExpr)
    wrong("a literal or a variable's name");
}

}  // namespace safegi::parser_detail
