#pragma once
// Diagnostic codes as data (codes.def): a constant per code for the call sites
// (`with_code(code::E_DIMENSION_MISMATCH)`), and each code's one-line meaning
// for docs/typechecker.md's table, `safeglslc --explain` and the language server.

#include <span>
#include <string>
#include <string_view>

namespace safegi {

namespace code {
#define CODE(id, text, meaning) inline constexpr char id[] = text;
#include "safegi/diagnostics/codes.def"
#undef CODE
}  // namespace code

struct DiagnosticCode {
  std::string_view code;
  std::string_view meaning;
};

// Every code, in codes.def's order.
std::span<const DiagnosticCode> diagnostic_codes();
// The entry of `code`, or nullptr when no diagnostic has that code.
const DiagnosticCode* find_diagnostic_code(std::string_view code);
// What `safeglslc --explain CODE` prints: the code, its meaning and where the
// documentation describes it; empty for an unknown code.
std::string explain_diagnostic_code(std::string_view code);

}  // namespace safegi
