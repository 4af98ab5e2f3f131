// Lines per second of safeglslc's front end (lex + preprocess + parse) beside
// glslang's parse of the same text, in the same process. glslang's parse also
// builds its typed intermediate tree (semantic analysis), so it does more per
// line; the comparison says what a separate SafeGI front end costs next to
// the validator users already run. Run: build/bin/safegi_frontend_bench
// (docs/frontend-corpus.md records the numbers).

#include <string>

#include <glslang/Public/ResourceLimits.h>

#include <safegi/lexer/preprocessor.hpp>
#include <safegi/parser/parser.hpp>

#include "frontend_bench_support.hpp"

namespace {

const std::string& shader() {
  static const std::string text = safegi::bench::plain_shader(1000);
  return text;
}

void BM_SafegiFrontEnd(benchmark::State& state) {
  const std::string& text = shader();
  for (auto _ : state) {
    safegi::SourceManager sources;
    safegi::DiagnosticEngine diagnostics;
    safegi::FileId file = sources.add_file("bench.frag", text);
    safegi::PreprocessedUnit unit = safegi::preprocess(sources, file, {}, diagnostics);
    safegi::ParseOptions options;
    options.language = unit.language;
    safegi::ParseResult parsed = safegi::parse(unit.tokens, diagnostics, options);
    if (diagnostics.has_errors()) state.SkipWithError("front end reported errors");
    benchmark::DoNotOptimize(parsed.unit);
  }
  safegi::bench::set_line_counters(state, text);
}
BENCHMARK(BM_SafegiFrontEnd)->Unit(benchmark::kMillisecond);

void BM_GlslangParse(benchmark::State& state) {
  safegi::bench::run_glslang(state, shader(), [](glslang::TShader& glsl) {
    return glsl.parse(GetDefaultResources(), 110, false, EShMsgDefault);
  });
}
BENCHMARK(BM_GlslangParse)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
