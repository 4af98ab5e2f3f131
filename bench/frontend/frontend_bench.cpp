// Lines per second of safeglslc's front end (lex + preprocess + parse) beside
// glslang's parse of the same text, in the same process. glslang's parse also
// builds its typed intermediate tree (semantic analysis), so it does more per
// line; the comparison says what a separate SafeGI front end costs next to
// the validator users already run. Run: build/bin/safegi_frontend_bench
// (docs/frontend-corpus.md records the numbers).

#include <string>

#include <benchmark/benchmark.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <safegi/lexer/preprocessor.hpp>
#include <safegi/parser/parser.hpp>

namespace {

// A large, plain GLSL 4.50 fragment shader: `functions` generated functions
// over a struct, a uniform block, macros, loops, switches and swizzles.
std::string generated_shader(int functions) {
  std::string s =
      "#version 450 core\n"
      "#define SCALE(x) ((x) * 0.5 + 0.5)\n"
      "#define COUNT 4\n"
      "struct Light { vec3 position; vec3 color; float radius; };\n"
      "layout(std140, binding = 0) uniform Lights { Light lights[COUNT]; mat4 view; } ubo;\n"
      "layout(binding = 1) uniform sampler2D albedo;\n"
      "layout(location = 0) in vec3 P;\n"
      "layout(location = 1) in vec3 N;\n"
      "layout(location = 2) in vec2 uv;\n"
      "layout(location = 0) out vec4 color;\n";
  for (int i = 0; i < functions; ++i) {
    std::string n = std::to_string(i);
    s += "vec3 shade" + n + "(vec3 p, vec3 n, int k) {\n"
         "    vec3 sum = vec3(0.0);\n"
         "    for (int j = 0; j < COUNT; ++j) {\n"
         "        Light l = ubo.lights[j];\n"
         "        vec3 d = l.position - p;\n"
         "        float r2 = dot(d, d);\n"
         "        if (r2 > l.radius * l.radius) continue;\n"
         "        float cosTheta = max(dot(normalize(n), d * inversesqrt(r2)), 0.0);\n"
         "        sum += l.color * cosTheta / (r2 + 1e-4) * SCALE(float(j + k));\n"
         "    }\n"
         "    switch (k & 3) {\n"
         "    case 0: sum.xy *= 2.0; break;\n"
         "    case 1: sum = sum.zyx; break;\n"
         "    default: sum += texture(albedo, uv * float(k + " + n + ")).rgb;\n"
         "    }\n"
         "    int bits = (k << 2) ^ (k >> 1) | " + n + ";\n"
         "    return bits % 2 == 0 ? sum : -sum;\n"
         "}\n";
  }
  s += "void main() {\n    vec3 c = vec3(0.0);\n";
  for (int i = 0; i < functions; i += 16) s += "    c += shade" + std::to_string(i) + "(P, N, " + std::to_string(i) + ");\n";
  s += "    color = vec4(c, 1.0);\n}\n";
  return s;
}

std::int64_t count_lines(const std::string& s) {
  std::int64_t n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

const std::string& shader() {
  static const std::string text = generated_shader(1000);
  return text;
}

void BM_SafegiFrontEnd(benchmark::State& state) {
  const std::string& text = shader();
  for (auto _ : state) {
    safegi::SourceManager sources;
    safegi::DiagnosticEngine diagnostics;
    safegi::FileId file = sources.add_file("bench.frag", text);
    safegi::PreprocessedUnit unit = safegi::preprocess(sources, file, {}, diagnostics);
    safegi::ParseResult parsed = safegi::parse(unit.tokens, diagnostics);
    if (diagnostics.has_errors()) state.SkipWithError("front end reported errors");
    benchmark::DoNotOptimize(parsed.unit);
  }
  state.counters["lines/s"] =
      benchmark::Counter(static_cast<double>(count_lines(text)), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["lines"] = static_cast<double>(count_lines(text));
}
BENCHMARK(BM_SafegiFrontEnd)->Unit(benchmark::kMillisecond);

void BM_GlslangParse(benchmark::State& state) {
  const std::string& text = shader();
  glslang::InitializeProcess();
  for (auto _ : state) {
    glslang::TShader glsl(EShLangFragment);
    const char* source = text.c_str();
    glsl.setStrings(&source, 1);
    if (!glsl.parse(GetDefaultResources(), 110, false, EShMsgDefault)) state.SkipWithError(glsl.getInfoLog());
  }
  glslang::FinalizeProcess();
  state.counters["lines/s"] =
      benchmark::Counter(static_cast<double>(count_lines(text)), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["lines"] = static_cast<double>(count_lines(text));
}
BENCHMARK(BM_GlslangParse)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
