#pragma once
// How every program reports a command line CLI11 rejects: "<program>: error:
// <what>", a pointer to --help, exit status kExitUsage (CLI11's own codes,
// 105, 106, ..., would mix with the input's). Header-only: include it where
// CLI11 is linked (the programs).

#include <iostream>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

#include <safegi/diagnostics/exit_status.hpp>
#include <safegi/diagnostics/printable.hpp>

namespace safegi {

// `code`, where the program's diagnostics have codes (safeglslc: E-COMMAND-LINE), ends the line.
inline std::string usage_error_text(const std::string& program, const std::string& what, std::string_view code = {}) {
  std::string text = program;
  text += ": error: ";
  text += escape_unprintable(what);
  if (!code.empty()) {
    text += " [";
    text += code;
    text += "]";
  }
  text += "\nRun with --help for usage.\n";
  return text;
}

// --help and --version print to `out` and exit 0; anything else is a usage error on `err`.
inline int exit_after_parse_error(const CLI::App& app, const CLI::ParseError& error, std::ostream& out = std::cout,
                                  std::ostream& err = std::cerr) {
  if (error.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(error, out, err);
  err << usage_error_text(app.get_name(), error.what());
  return kExitUsage;
}

}  // namespace safegi
