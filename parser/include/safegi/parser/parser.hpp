#pragma once
// The parser: a token stream from the preprocessor in, a syntax tree out.
// Syntax errors are reported to the DiagnosticEngine (several per run, one per
// mistake); the tree then holds everything that could be parsed.

#include <memory>
#include <optional>
#include <span>
#include <string_view>

#include <safegi/diagnostics/diagnostic.hpp>
#include <safegi/diagnostics/source_location.hpp>
#include <safegi/lexer/extensions.hpp>
#include <safegi/lexer/token.hpp>
#include <safegi/parser/ast.hpp>

namespace safegi {

struct ParseOptions {
  // Nesting of statements, parentheses, unary operators and annotations the
  // parser follows before reporting "nesting too deep" (never a stack overflow).
  unsigned max_nesting = 256;
  // Height of any expression tree (long left-associative chains included).
  unsigned max_expression_height = 2048;
  // The shader's #version and extensions (PreprocessedUnit::language): syntax
  // they do not allow is an error, e.g. "arrays of arrays require #version 430
  // or GL_ARB_arrays_of_arrays". Unset: every feature is allowed.
  std::optional<LanguageLevel> language;
};

struct ParseResult {
  std::unique_ptr<ast::AstContext> context;
  ast::TranslationUnit* unit = nullptr;  // never null, possibly partial after errors
};

// `tokens`: the preprocessor's output, ending with an eof token. Words are
// taken as the lexer classified them for the shader's #version; SafeGI's
// annotation words arrive as identifiers and get their meaning here.
ParseResult parse(std::span<const Token> tokens, DiagnosticEngine& diagnostics,
                  const ParseOptions& options = {});

}  // namespace safegi
