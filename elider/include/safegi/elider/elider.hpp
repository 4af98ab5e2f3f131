#pragma once
// The elider: turns a checked SafeGI translation unit into the plain GLSL a
// driver accepts (docs/language.md, "Erasure") and describes its interface as
// a symbol table (docs/symbol-table.md).
//
// Erasure blanks bytes and never moves a line: annotations become spaces,
// annotated type words their representation, annotation declarations and
// template headers disappear, units become their scale and geometric
// operations become the GLSL a careful programmer would write
// (`(m * vec4(p, 1.0)).xyz`). Text of user `#include`d files is inlined
// between `#line` directives, so driver line numbers are the user's.

#include <string>
#include <utility>
#include <vector>

#include <safegi/diagnostics/diagnostic.hpp>
#include <safegi/diagnostics/source_manager.hpp>
#include <safegi/lexer/preprocessor.hpp>
#include <safegi/parser/ast.hpp>
#include <safegi/symbol_table/symbol_table.hpp>
#include <safegi/typechecker/checker.hpp>

namespace safegi {

struct ElideInput {
  const SourceManager& sources;
  FileId main_file = kNoFile;
  const PreprocessedUnit& preprocessed;
  const ast::TranslationUnit& unit;
  const CheckResult& checked;
  // -D / -U given to the compiler; re-emitted after #version so the driver
  // takes the same #if branches the checker saw.
  std::vector<std::pair<std::string, std::string>> defines;
  std::vector<std::string> undefines;
  // Off: only the checks the erasure makes (its diagnostics); no text.
  bool render = true;
};

struct ElideResult {
  std::string glsl;
  // `#line N S` source-string number -> file path (0 is the main file).
  std::vector<std::string> source_files;
  std::vector<std::string> helpers;  // names of the generated helpers used
};

// Problems (a geometric operation whose operands come from different macro
// expansions, which cannot be rewritten in place) are reported to `diagnostics`.
ElideResult elide(const ElideInput& input, DiagnosticEngine& diagnostics);

// The interface of one checked stage, in the symbol table's words. `file` is
// the annotated source as the user named it.
gl::StageSymbols stage_symbols(const ElideInput& input, gl::Stage stage, const std::string& file,
                               const std::vector<std::string>& source_files);

// Adds the base/derived dimensions, units and spaces the unit declares (the
// prelude's included) to `table`, skipping names already there.
void add_declarations(gl::SymbolTable& table, const ElideInput& input);

// Keeps the base dimensions, units and spaces the table's symbols use, every derived
// dimension (readers name exponent vectors by them), and every entry its programs declare
// themselves; the prelude's others are named by `table.vocabulary` (the prelude's name and
// a hash of its entries), not listed.
void trim_vocabulary(gl::SymbolTable& table);

// "fnv1a64:<16 hex digits>" of `text`.
std::string source_hash(std::string_view text);

}  // namespace safegi
