// Throughput of the raw lexer and of the preprocessor (MB/s and lines/s) on a
// large generated shader that leans on the preprocessor: comments, line
// continuations, object- and function-like macros, token pasting and
// conditionals; beside glslang's own preprocessor (TShader::preprocess) on
// the same text in the same process. Run: build/bin/safegi_lex_bench

#include <string>

#include <glslang/Public/ResourceLimits.h>

#include <safegi/lexer/lexer.hpp>
#include <safegi/lexer/preprocessor.hpp>

#include "frontend_bench_support.hpp"

namespace {

const std::string& shader() {
  static const std::string text = safegi::bench::preprocessor_heavy_shader(4000);
  return text;
}

void BM_SafegiLex(benchmark::State& state) {
  const std::string& text = shader();
  for (auto _ : state) {
    safegi::SourceManager sources;
    safegi::DiagnosticEngine diagnostics;
    auto tokens = safegi::tokenize(sources, sources.add_file("bench.frag", text), diagnostics);
    benchmark::DoNotOptimize(tokens.data());
  }
  safegi::bench::set_line_counters(state, text);
}
BENCHMARK(BM_SafegiLex)->Unit(benchmark::kMillisecond);

void BM_SafegiPreprocess(benchmark::State& state) {
  const std::string& text = shader();
  for (auto _ : state) {
    safegi::SourceManager sources;
    safegi::DiagnosticEngine diagnostics;
    auto unit = safegi::preprocess(sources, sources.add_file("bench.frag", text), {}, diagnostics);
    if (diagnostics.has_errors()) state.SkipWithError("the preprocessor reported errors");
    benchmark::DoNotOptimize(unit.tokens.data());
  }
  safegi::bench::set_line_counters(state, text);
}
BENCHMARK(BM_SafegiPreprocess)->Unit(benchmark::kMillisecond);

void BM_GlslangPreprocess(benchmark::State& state) {
  safegi::bench::run_glslang(state, shader(), [](glslang::TShader& glsl) {
    std::string output;
    glslang::TShader::ForbidIncluder includer;
    bool ok = glsl.preprocess(GetDefaultResources(), 110, ENoProfile, false, false, EShMsgDefault, &output, includer);
    benchmark::DoNotOptimize(output.data());
    return ok;
  });
}
BENCHMARK(BM_GlslangPreprocess)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
