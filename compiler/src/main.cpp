// safeglslc and safeglslc-spirv: see docs/safeglslc.md. One source, two
// programs: safeglslc never links glslang, so its start-up costs what the
// checker costs; given a SPIR-V flag it becomes safeglslc-spirv (built with
// SAFEGLSLC_SPIRV, the same command with safegi::to_spirv) by exec, before
// reading any input.
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>

#include <safegi/diagnostics/codes.hpp>
#include <safegi/diagnostics/exit_status.hpp>
#include <safegi/diagnostics/printable.hpp>

#include "safegi/compiler/cli.hpp"
#if SAFEGLSLC_SPIRV
#include "safegi/compiler/spirv.hpp"
#endif

namespace {

#if !SAFEGLSLC_SPIRV
// Replaces this process with safeglslc-spirv from this program's directory;
// returns only when that fails (with the reason on stderr).
void become_spirv_compiler(char** argv) {
  char self[PATH_MAX];
  const ssize_t length = readlink("/proc/self/exe", self, sizeof self - 1);
  if (length <= 0) {
    std::fprintf(stderr, "safeglslc: error: cannot find this program's path to run safeglslc-spirv: %s [%s]\n",
                 std::strerror(errno), safegi::code::E_SPIRV);
    return;
  }
  std::string path(self, static_cast<std::size_t>(length));
  path = path.substr(0, path.rfind('/') + 1) + "safeglslc-spirv";
  argv[0] = path.data();
  execv(path.c_str(), argv);
  std::fprintf(stderr, "safeglslc: error: SPIR-V output runs %s, which could not be started: %s [%s]\n", path.c_str(),
               std::strerror(errno), safegi::code::E_SPIRV);
}
#endif

}  // namespace

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  std::vector<std::string> args(argv + 1, argv + argc);
#if SAFEGLSLC_SPIRV
  const safegi::SpirvBackend backend = &safegi::to_spirv;
#else
  const safegi::SpirvBackend backend = nullptr;
  if (safegi::wants_spirv(args)) {
    become_spirv_compiler(argv);
    return 2;
  }
#endif
  safegi::CliStreams io{std::cin, std::cout, std::cerr, isatty(fileno(stderr)) != 0};
  try {
    const int status = safegi::run_safeglslc(args, io, backend);
    std::cout.flush();
    return status;
  } catch (const std::bad_alloc&) {
    std::string what = safegi::out_of_memory_text("compiling");
    what += " [";
    what += safegi::code::E_LIMIT;
    what += ']';
    std::cerr << "safeglslc: " << safegi::error_report(what);
    return safegi::kExitInputError;
  }
}
