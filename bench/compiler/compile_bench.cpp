// In-process cost of safegi::compile (preprocess + parse + check + elide +
// symbol table) on each annotated example shader, beside glslang parsing the
// GLSL that safeglslc emits for it (what a driver front end does), and beside
// the same compile keeping its analysis with the checker's symbols, as
// safegi-lsp compiles (CompileOptions::keep_analysis).
//
//   build/bin/safegi_bench_compiler
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "glslang_check.hpp"
#include "safegi/compiler/compile.hpp"

namespace {

namespace fs = std::filesystem;

void bm_safegi_compile(benchmark::State& state, fs::path path, bool keep_analysis) {
  const std::string text = safegi::testing::read_text_file(path);
  const std::string name = path.filename().string();
  safegi::CompileOptions options;
  options.keep_analysis = keep_analysis;
  for (auto _ : state) {
    safegi::CompileResult r = safegi::compile({{name, text}}, options);
    if (!r.success) state.SkipWithError("compile failed");
    benchmark::DoNotOptimize(r);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}

void bm_glslang_parse(benchmark::State& state, fs::path path) {
  safegi::CompileResult r = safegi::compile({{path.filename().string(), safegi::testing::read_text_file(path)}});
  const std::string glsl = r.stages.at(0).glsl;
  const safegi::Stage stage = r.stages.at(0).stage;
  for (auto _ : state) {
    safegi::testing::GlslangVerdict v = safegi::testing::glslang_validate(glsl, stage);
    if (!v.accepted) state.SkipWithError("glslang rejected");
    benchmark::DoNotOptimize(v);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * glsl.size()));
}

const bool registered = [] {
  std::vector<fs::path> examples;
  for (const auto& e : fs::directory_iterator(SAFEGI_EXAMPLE_SHADERS))
    if (e.path().filename().string().find(".sgl.") != std::string::npos) examples.push_back(e.path());
  std::sort(examples.begin(), examples.end());
  for (const fs::path& p : examples) {
    // compile() runs on a thread of its own (a large stack): the process's CPU
    // time counts it, the calling thread's would not.
    benchmark::RegisterBenchmark(("safegi_compile/" + p.filename().string()).c_str(), bm_safegi_compile, p, false)
        ->Unit(benchmark::kMicrosecond)
        ->MeasureProcessCPUTime();
    benchmark::RegisterBenchmark(("safegi_compile_keep_analysis/" + p.filename().string()).c_str(), bm_safegi_compile, p,
                                 true)
        ->Unit(benchmark::kMicrosecond)
        ->MeasureProcessCPUTime();
    benchmark::RegisterBenchmark(("glslang_parse/" + p.filename().string()).c_str(), bm_glslang_parse, p)
        ->Unit(benchmark::kMicrosecond);
  }
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
