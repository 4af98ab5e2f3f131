#include <safegi/parser/parser.hpp>

#include "parser_impl.hpp"

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
