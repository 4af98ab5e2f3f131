#pragma once
// Checks a shader given as text: prelude (optional) + source, raw lexer,
// parser, checker. Diagnostics are rendered as text for exact comparisons.

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <safegi/diagnostics/diagnostic.hpp>
#include <safegi/diagnostics/source_manager.hpp>
#include <safegi/lexer/token.hpp>
#include <safegi/parser/parser.hpp>

#include "safegi/typechecker/checker.hpp"

namespace safegi::testing {

struct CheckedSource {
  SourceManager sources;
  DiagnosticEngine diagnostics;
  std::vector<Token> tokens;
  ParseResult parsed;
  CheckResult result;

  // "error: message" lines, one per diagnostic (notes and hints excluded).
  std::vector<std::string> messages() const;
  // The clang-style rendering of every diagnostic.
  std::string rendered() const;
  std::size_t errors() const { return diagnostics.error_count(); }
};

struct SourceOptions {
  Stage stage = Stage::fragment;
  bool prelude = true;
  bool strict = false;
  std::optional<LanguageLevel> language = {};  // the version-dependent rules run only with one
  bool symbols = false;  // CheckOptions::record_symbols
};

std::unique_ptr<CheckedSource> check_source(std::string_view source, SourceOptions options = {});

// The checked type of the variable `name` declared anywhere in the program, printed.
std::string declared_type(const CheckedSource& c, std::string_view name);

}  // namespace safegi::testing
