#pragma once
// The safeglslc command as a function, so tests (the golden runner) run it
// in-process with their own streams. main() only wires up the real ones.

#include <iosfwd>
#include <string>
#include <vector>

namespace safegi {

struct CliStreams {
  std::istream& in;
  std::ostream& out;
  std::ostream& err;
  bool err_is_terminal = false;  // colour only when true (and --color=auto)
};

// `args` without the program name. Returns the exit status: 0 success,
// 1 diagnostics with errors, 2 usage or I/O error.
int run_safeglslc(const std::vector<std::string>& args, CliStreams& io);

}  // namespace safegi
