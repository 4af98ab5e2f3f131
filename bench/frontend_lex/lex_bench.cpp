// Throughput of the raw lexer and of the preprocessor (MB/s and lines/s) on a
// large generated shader that leans on the preprocessor: comments, line
// continuations, object- and function-like macros, token pasting and
// conditionals; beside glslang's own preprocessor (TShader::preprocess) on
// the same text in the same process. Run: build/bin/safegi_lex_bench

#include <string>

#include <benchmark/benchmark.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <safegi/lexer/lexer.hpp>
#include <safegi/lexer/preprocessor.hpp>

namespace {

std::string preprocessor_heavy_shader(int blocks) {
  std::string s =
      "#version 450 core\n"
      "// Generated for the lexer benchmark.\n"
      "#define PI 3.14159265358979\n"
      "#define SATURATE(x) clamp((x), 0.0, 1.0)\n"
      "#define LERP(a, b, t) ((a) + ((b) - (a)) * (t))\n"
      "#define FIELD(name, n) name ## n\n"
      "#define QUALITY 2\n"
      "layout(location = 0) out vec4 fragColor;\n";
  for (int i = 0; i < blocks; ++i) {
    std::string n = std::to_string(i);
    s += "/* block " + n + ": a multi-line comment\n   that the lexer skips */\n"
         "uniform vec4 FIELD(tint, " + n + ");\n"
         "float falloff" + n + "(float d, float r) {  // inverse square with a window\n"
         "    float w = SATURATE(1.0 - pow(d / r, 4.0));\n"
         "    return w * w / (d * d + 1e-4) * (1.0 / (4.0 * PI));\n"
         "}\n"
         "#if QUALITY > 1 && defined(PI)\n"
         "vec3 mix" + n + "(vec3 a, vec3 b, float t) { return LERP(a, b, SATURATE(t)) + \\\n"
         "    vec3(0x1Fu & " + n + "u, 017, .5e-2); }\n"
         "#else\n"
         "vec3 mix" + n + "(vec3 a, vec3 b, float t) { return a; }\n"
         "#endif\n";
  }
  s += "void main() { fragColor = vec4(mix0(vec3(1.0), vec3(0.0), falloff0(1.0, 2.0)), 1.0); }\n";
  return s;
}

const std::string& shader() {
  static const std::string text = preprocessor_heavy_shader(4000);
  return text;
}

void set_counters(benchmark::State& state, const std::string& text) {
  std::int64_t lines = 0;
  for (char c : text) lines += c == '\n';
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(text.size()));
  state.counters["lines/s"] = benchmark::Counter(static_cast<double>(lines), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["lines"] = static_cast<double>(lines);
}

void BM_SafegiLex(benchmark::State& state) {
  const std::string& text = shader();
  for (auto _ : state) {
    safegi::SourceManager sources;
    safegi::DiagnosticEngine diagnostics;
    auto tokens = safegi::tokenize(sources, sources.add_file("bench.frag", text), diagnostics);
    benchmark::DoNotOptimize(tokens.data());
  }
  set_counters(state, text);
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
  set_counters(state, text);
}
BENCHMARK(BM_SafegiPreprocess)->Unit(benchmark::kMillisecond);

void BM_GlslangPreprocess(benchmark::State& state) {
  const std::string& text = shader();
  glslang::InitializeProcess();
  for (auto _ : state) {
    glslang::TShader glsl(EShLangFragment);
    const char* source = text.c_str();
    glsl.setStrings(&source, 1);
    std::string output;
    glslang::TShader::ForbidIncluder includer;
    if (!glsl.preprocess(GetDefaultResources(), 110, ENoProfile, false, false, EShMsgDefault, &output, includer)) {
      state.SkipWithError(glsl.getInfoLog());
    }
    benchmark::DoNotOptimize(output.data());
  }
  glslang::FinalizeProcess();
  set_counters(state, text);
}
BENCHMARK(BM_GlslangPreprocess)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
