// libFuzzer target over the whole pipeline: preprocess, parse, check, elide,
// symbol table, diagnostics rendering. Any crash, sanitizer report, hang or
// broken invariant is a bug; each one found becomes a golden case.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

#include "safegi/compiler/compile.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  safegi::CompileOptions options;
  // Only the built-in prelude: the fuzzer never reads the file system.
  options.read_file = [](const std::string&) -> std::optional<std::string> { return std::nullopt; };
  options.diagnostics.error_limit = 50;
  const safegi::Stage stage = size % 2 == 0 ? safegi::Stage::fragment : safegi::Stage::vertex;
  safegi::CompileResult result = safegi::compile({{"fuzz.sgl", text, stage}}, options);
  (void)result.diagnostics_text();
  (void)result.diagnostics_json();
  if (!result.success) return 0;
  (void)result.symbols_json();
  // Invariant: erasure never moves a line (without includes or helpers it
  // does not even add one).
  const std::string& glsl = result.stages.at(0).glsl;
  if (glsl.find("#line") == std::string::npos) {
    const auto lines = [](const std::string& s) { return std::count(s.begin(), s.end(), '\n'); };
    if (lines(glsl) != lines(text)) __builtin_trap();
  }
  return 0;
}
