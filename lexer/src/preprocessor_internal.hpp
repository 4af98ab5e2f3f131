#pragma once
// Pieces of the preprocessor shared between its source files; not installed.

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include <safegi/diagnostics/diagnostic.hpp>
#include <safegi/lexer/token.hpp>

namespace safegi::detail {

// A token inside the preprocessor: `no_expand` marks a macro name met while
// that macro was being expanded; it must never expand later (C 6.10.3.4).
struct PPToken {
  Token token;
  bool no_expand = false;
};

struct Macro {
  enum class Builtin : std::uint8_t { none, line, file };
  std::string_view name;
  Builtin builtin = Builtin::none;
  bool predefined = false;  // __LINE__, GL_ES, ...: cannot be redefined or undefined
  bool function_like = false;
  bool disabled = false;    // being expanded
  std::vector<std::string_view> params;
  std::vector<Token> body;
  SourceRange name_range;   // invalid for predefined macros
  SourceRange paste_at_edge;  // a '##' that begins or ends the body: expanding is an error

  bool same_definition(const Macro& other) const;
  int param_index(std::string_view word) const;
};

struct ExpressionContext {
  bool es = false;          // undefined identifiers are errors in ES, 0 with a warning otherwise
  int max_depth = 256;
};

// Evaluates a fully macro-expanded #if / #elif expression (the `defined`
// operator already replaced by 0 / 1). Reports problems and returns nullopt.
std::optional<std::int64_t> evaluate_expression(const std::vector<Token>& tokens, SourceRange directive,
                                                const ExpressionContext& context, DiagnosticEngine& diagnostics);

}  // namespace safegi::detail
