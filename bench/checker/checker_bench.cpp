// Lines per second of the type checker beside the front end, on one large
// generated annotated shader (the prelude's dimensions, spaces, maps, generic
// functions instantiated at every call, inferred locals, texture lookups).
//
//   build/bin/safegi_checker_bench [--lines N] [--print] [benchmark flags]
//   (--print writes the generated shader to stdout instead of measuring)
//
// BM_Parse: preprocess (prelude included) + parse.  BM_ParseAndCheck: the
// same plus the type check.  BM_CheckOnly: the check of an already parsed
// tree.  Each reports lines/s of the generated text (prelude lines excluded).
// bench/checker/run.py turns the JSON output into docs/benchmarks.md's section.

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include <safegi/lexer/preprocessor.hpp>
#include <safegi/parser/parser.hpp>
#include <safegi/typechecker/checker.hpp>

namespace {

int g_target_lines = 50000;

// One block of annotated code per index: a generic helper, a space-generic
// helper and a shading function using maps, points, directions and spectra.
std::string block(int i) {
  const std::string n = std::to_string(i);
  return "template<dimension D>\n"
         "float<D> lerp" + n + "(float<D> a, float<D> b, float<1> x) { return a + (b - a) * x; }\n"
         "template<space S>\n"
         "float<length> gap" + n + "(point<S> a, point<S> b) { return length(a - b); }\n"
         "spectrum<radiance> shade" + n + "(point<object> pObject, normal<object> nObject, int k) {\n"
         "    point<world> p = worldFromObject * pObject;\n"
         "    normal<world> n = normalize(worldFromObject * nObject);\n"
         "    vector<world> toLight = lightPos - p;\n"
         "    float<length> d = gap" + n + "(lightPos, p);\n"
         "    direction<world> wi = normalize(toLight);\n"
         "    float<proj> cosTheta = max(dot(n, wi), 0.0);\n"
         "    float<length> r = lerp" + n + "(near, far, float(k) * 0.25);\n"
         "    float<1> shadow = step(texture(depthMap, vec2(0.5)).r, d) * (r / far);\n"
         "    float<solid_angle / (area * proj)> falloff = float<solid_angle / (area * proj)>(1.0 / (d * d));\n"
         "    return Kd * lightI * cosTheta * falloff * (1.0 - shadow);\n"
         "}\n";
}

const char* kHeader =
    "#version 330 core\n"
    "#include <safegi/prelude.sgl>\n"
    "space world;\n"
    "space object;\n"
    "uniform map<object, world> worldFromObject;\n"
    "uniform point<world> lightPos;\n"
    "uniform spectrum<intensity> lightI;\n"
    "uniform spectrum<brdf> Kd;\n"
    "uniform float<length> near;\n"
    "uniform float<length> far;\n"
    "uniform sampler2D<float<length>> depthMap;\n"
    "in point<object> P;\n"
    "in normal<object> N;\n"
    "out vec4 fragColor;\n";

struct Shader {
  std::string text;
  long long lines = 0;
};

const Shader& shader() {
  static const Shader s = [] {
    Shader out;
    out.text = kHeader;
    auto lines_of = [](const std::string& text) {
      long long c = 0;
      for (char ch : text) c += ch == '\n';
      return c;
    };
    long long lines = lines_of(out.text);
    std::vector<int> blocks;
    for (int i = 0; lines < g_target_lines - 8; ++i) {
      const std::string b = block(i);
      out.text += b;
      lines += lines_of(b);
      blocks.push_back(i);
    }
    out.text += "void main() {\n    spectrum<radiance> L = spectrum<radiance>(0.0);\n";
    for (int b = 0; b < static_cast<int>(blocks.size()); b += 64) out.text += "    L += shade" + std::to_string(b) + "(P, normalize(N), " + std::to_string(b) + ");\n";
    out.text += "    fragColor = vec4(L, 1.0);\n}\n";
    out.lines = lines_of(out.text);
    return out;
  }();
  return s;
}

struct Parsed {
  safegi::SourceManager sources;
  safegi::DiagnosticEngine diagnostics;
  safegi::PreprocessedUnit unit;
  safegi::ParseResult parsed;
};

void front_end(Parsed& p) {
  safegi::FileId file = p.sources.add_file("bench.sgl.frag", shader().text);
  safegi::PreprocessorOptions options;
  options.include_paths.push_back(SAFEGI_PRELUDE_DIR);
  p.unit = safegi::preprocess(p.sources, file, options, p.diagnostics);
  p.parsed = safegi::parse(p.unit.tokens, p.diagnostics);
}

// As safegi::compile checks: with the tokens (macro-expansion notes, map sizing).
safegi::CheckOptions options_for(const Parsed& p) {
  safegi::CheckOptions options;
  options.stage = safegi::Stage::fragment;
  options.tokens = &p.unit.tokens;
  options.sources = &p.sources;
  return options;
}

void count_lines(benchmark::State& state) {
  state.counters["lines"] = static_cast<double>(shader().lines);
  state.counters["lines_per_s"] =
      benchmark::Counter(static_cast<double>(shader().lines), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_Parse(benchmark::State& state) {
  for (auto _ : state) {
    Parsed p;
    front_end(p);
    if (p.diagnostics.has_errors()) state.SkipWithError("front end reported errors");
    benchmark::DoNotOptimize(p.parsed.unit);
  }
  count_lines(state);
}

void BM_ParseAndCheck(benchmark::State& state) {
  for (auto _ : state) {
    Parsed p;
    front_end(p);
    safegi::CheckResult r = safegi::check(*p.parsed.unit, options_for(p), p.diagnostics);
    if (p.diagnostics.has_errors()) state.SkipWithError("parse or check reported errors");
    benchmark::DoNotOptimize(r.types.size());
  }
  count_lines(state);
}

void BM_CheckOnly(benchmark::State& state) {
  Parsed p;
  front_end(p);
  for (auto _ : state) {
    safegi::DiagnosticEngine diagnostics;
    safegi::CheckResult r = safegi::check(*p.parsed.unit, options_for(p), diagnostics);
    if (diagnostics.has_errors()) state.SkipWithError("check reported errors");
    benchmark::DoNotOptimize(r.types.size());
  }
  count_lines(state);
}

BENCHMARK(BM_Parse)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ParseAndCheck)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CheckOnly)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  std::vector<char*> rest;
  bool print = false;
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--lines") == 0 && i + 1 < argc) g_target_lines = std::atoi(argv[++i]);
    else if (std::strcmp(argv[i], "--print") == 0) print = true;
    else rest.push_back(argv[i]);
  }
  if (print) {
    std::fputs(shader().text.c_str(), stdout);
    return 0;
  }
  int count = static_cast<int>(rest.size());
  benchmark::Initialize(&count, rest.data());
  if (benchmark::ReportUnrecognizedArguments(count, rest.data())) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
