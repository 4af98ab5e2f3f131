// The table of diagnostic codes, from codes.def.

#include "safegi/diagnostics/codes.hpp"

#include <array>

namespace safegi {
namespace {

constexpr std::array kCodes = {
#define CODE(id, text, meaning) DiagnosticCode{text, meaning},
#include "safegi/diagnostics/codes.def"
#undef CODE
};

}  // namespace

std::span<const DiagnosticCode> diagnostic_codes() { return kCodes; }

const DiagnosticCode* find_diagnostic_code(std::string_view code) {
  for (const DiagnosticCode& c : kCodes)
    if (c.code == code) return &c;
  return nullptr;
}

std::string explain_diagnostic_code(std::string_view code) {
  const DiagnosticCode* c = find_diagnostic_code(code);
  if (!c) return {};
  const bool warning = code.starts_with("W-");
  return std::string(c->code) + ": " + std::string(c->meaning) + ".\n\n" + (warning ? "A warning" : "An error") +
         " of safeglslc. docs/typechecker.md (\"Diagnostics\") lists every code of every stage; docs/language.md "
         "and docs/preprocessor.md give the rules they enforce.\n";
}

}  // namespace safegi
