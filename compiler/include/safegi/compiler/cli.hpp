#pragma once
// The safeglslc command as a function, so tests (the golden runner) run it
// in-process with their own streams. main() only wires up the real ones.

#include <iosfwd>
#include <string>
#include <vector>

namespace safegi {

struct CompileResult;
struct SpirvOptions;
struct SpirvResult;

// What turns a compile into SPIR-V for -V/-G: safegi::to_spirv, which links
// glslang. The plain `safeglslc` passes none and, before parsing anything,
// hands a SPIR-V command line to `safeglslc-spirv` beside it (wants_spirv), so
// the checker's own start-up never pays for glslang.
using SpirvBackend = SpirvResult (*)(const CompileResult&, const SpirvOptions&);

// Whether `args` ask for SPIR-V or give a SPIR-V-only flag (-V[ver], -G[ver],
// --client, --target-env, --aml, --amb, -R, -g).
bool wants_spirv(const std::vector<std::string>& args);

struct CliStreams {
  std::istream& in;
  std::ostream& out;
  std::ostream& err;
  bool err_is_terminal = false;  // colour only when true (and --color=auto)
};

// `args` without the program name. Returns the exit status: 0 success,
// 1 diagnostics with errors, 2 usage or I/O error (also SPIR-V asked of a
// call without a backend).
int run_safeglslc(const std::vector<std::string>& args, CliStreams& io, SpirvBackend spirv_backend = nullptr);

}  // namespace safegi
