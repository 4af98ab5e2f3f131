// libFuzzer target: any bytes as a shader (with one includable file) through
// the preprocessor and both diagnostic renderers. Built with clang when
// SAFEGI_FUZZ=ON; run: build/bin/safegi_preprocess_fuzzer -max_total_time=60

#include <cstddef>
#include <cstdint>
#include <string>

#include <safegi/diagnostics/render.hpp>
#include <safegi/lexer/preprocessor.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  safegi::SourceManager sources;
  safegi::DiagnosticEngine diagnostics({.error_limit = 50});
  safegi::PreprocessorOptions options;
  options.max_output_tokens = 1u << 16;
  options.max_include_count = 16;
  // The input can include itself or a second copy of itself: exercises cycles and repeats.
  options.read_file = [&text](const std::string& path) -> std::optional<std::string> {
    if (path == "fuzz.glsl" || path == "inc/fuzz.glsl") return text;
    return std::nullopt;
  };
  options.include_paths = {"inc"};
  safegi::FileId file = sources.add_file("main.glsl", text);
  safegi::PreprocessedUnit unit = safegi::preprocess(sources, file, options, diagnostics);
  if (unit.tokens.empty() || unit.tokens.back().kind != safegi::TokenKind::eof) __builtin_trap();
  (void)safegi::render_text(diagnostics.diagnostics(), sources);
  (void)safegi::render_json(diagnostics.diagnostics(), sources);
  return 0;
}
