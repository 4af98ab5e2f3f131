#pragma once
// Helpers for the parser tests: parse a string, render its diagnostics, and
// ask glslang whether printed GLSL is valid.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <safegi/diagnostics/diagnostic.hpp>
#include <safegi/diagnostics/source_manager.hpp>
#include <safegi/lexer/token.hpp>
#include <safegi/parser/parser.hpp>
#include <safegi/parser/printer.hpp>

namespace safegi::testing {

struct Parsed {
  SourceManager sources;
  DiagnosticEngine diagnostics;
  std::vector<Token> tokens;
  ParseResult result;

  const ast::TranslationUnit& unit() const { return *result.unit; }
  std::string dump() const { return dump_ast(*result.unit); }
  std::string errors() const;  // rendered diagnostics, "" when none
  std::string glsl(bool annotations = true) const;
};

// Lexes `source` as GLSL 4.60 (no preprocessing) and parses it.
std::unique_ptr<Parsed> parse_text(std::string_view source, ParseOptions options = {});

// The dump of the first declaration's first statement, or of the first
// declaration when it is not a function: keeps per-construct tests short.
std::string dump_first(std::string_view source);

// The expression `source` as a dump (parsed inside `void f() { x = source; }`
// style wrapper: the initialiser of `float t = <source>;`).
std::string dump_expr(std::string_view source);

// glslang accepts `glsl` (with its #version line) as a `stage` shader:
// "vert", "frag", "comp", "geom", "tesc", "tese". On failure *log gets its log.
bool glslang_accepts(const std::string& glsl, std::string_view stage, std::string* log = nullptr);

}  // namespace safegi::testing
