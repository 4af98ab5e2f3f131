#include <safegi/parser/parser.hpp>

#include "parser_impl.hpp"

namespace safegi::parser_detail {

using namespace ast;

Parser::Parser(std::vector<PToken> tokens, DiagnosticEngine& diagnostics, const ParseOptions& options,
               AstContext& context)
    : tokens_(std::move(tokens)), diagnostics_(diagnostics), options_(options), context_(context) {
  if (tokens_.empty() || tokens_.back().kind != T::Eof) {
    PToken eof;
    if (!tokens_.empty()) eof.range = {tokens_.back().range.end, tokens_.back().range.end};
    tokens_.push_back(eof);
  }
  prev_end_ = tokens_.front().range.begin;
  push_scope();
  // Built-in struct types (compatibility profile uniforms) and the opaque
  // types of extensions glslang accepts in OpenGL GLSL but the lexer does not
  // list as keywords; a program's own declaration shadows them.
  for (const char* name : {"gl_DepthRangeParameters", "gl_PointParameters", "gl_MaterialParameters",
                           "gl_LightSourceParameters", "gl_LightModelParameters", "gl_LightModelProducts",
                           "gl_LightProducts", "gl_FogParameters", "accelerationStructureEXT",
                           "accelerationStructureNV", "rayQueryEXT", "hitObjectNV"}) {
    declare(name, NameKind::Type);
  }
  push_scope();  // the program's global scope
}

// ----------------------------------------------------------------- errors

void Parser::fail(const char* code, SourceRange range, std::string message) {
  // One "end of file" error per run: the enclosing constructs that are also
  // left open would only repeat it.
  if (at(T::Eof) && range == peek().range) {
    if (eof_reported_) throw ParseError{};
    eof_reported_ = true;
    range = {prev_end_, prev_end_};  // where the missing text should have been
  }
  diagnostics_.report(Diagnostic::error(range, std::move(message)).with_code(code));
  throw ParseError{};
}

void Parser::fail_expected(std::string_view what, std::string_view context) {
  std::string message = "expected " + std::string(what);
  if (!context.empty()) message += " " + std::string(context);
  message += ", found " + describe(peek());
  fail(code::E_SYNTAX, peek().range, std::move(message));
}

const PToken& Parser::expect(T kind, std::string_view what, std::string_view context) {
  if (!at(kind)) fail_expected(what, context);
  return advance();
}

void Parser::expect_semicolon(std::string_view context) {
  if (accept(T::Semicolon)) return;
  // Like clang: the caret goes just after the previous token, where the ';' is missing.
  std::string message = "expected ';' " + std::string(context) + ", found " + describe(peek());
  SourceRange at_end{prev_end_, prev_end_};
  diagnostics_.report(Diagnostic::error(at_end, std::move(message)).with_code(code::E_SYNTAX));
  throw ParseError{};
}

void Parser::enter_level() {
  if (++depth_ > options_.max_nesting) {
    --depth_;
    if (!depth_reported_) {
      depth_reported_ = true;
      fail(code::E_LIMIT, peek().range,
           "nesting too deep: more than " + std::to_string(options_.max_nesting) +
               " levels of blocks, parentheses, brackets or operators");
    }
    throw ParseError{};
  }
}

Parser::DepthGuard::DepthGuard(Parser& p) : parser(p) { parser.enter_level(); }

void Parser::NestingLevels::add() {
  parser.enter_level();
  ++taken;
}

// ----------------------------------------------------------------- scopes

void Parser::declare(std::string_view name, NameKind kind) {
  if (!name.empty()) scopes_.back()[std::string(name)] = kind;
}

const Parser::NameKind* Parser::lookup(std::string_view name) const {
  std::string key(name);
  for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
    auto found = it->find(key);
    if (found != it->end()) return &found->second;
  }
  return nullptr;
}

bool Parser::is_type_name(std::string_view name) const {
  const NameKind* kind = lookup(name);
  return kind != nullptr && *kind == NameKind::Type;
}

}  // namespace safegi::parser_detail

namespace safegi {

ParseResult parse(std::span<const Token> tokens, DiagnosticEngine& diagnostics, const ParseOptions& options) {
  std::vector<parser_detail::PToken> view;
  view.reserve(tokens.size() + 1);
  for (const Token& token : tokens) {
    parser_detail::append_lexer_token(view, token);
    if (token.kind == TokenKind::eof) break;
  }
  ParseResult result;
  result.context = std::make_unique<ast::AstContext>();
  parser_detail::Parser parser(std::move(view), diagnostics, options, *result.context);
  result.unit = parser.parse_translation_unit();
  return result;
}

}  // namespace safegi
