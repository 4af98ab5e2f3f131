#include "frontend_bench_support.hpp"

#include <glslang/Public/ResourceLimits.h>

namespace safegi::bench {

std::string plain_shader(int functions) {
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

void set_line_counters(benchmark::State& state, const std::string& text) {
  std::int64_t lines = 0;
  for (char c : text) lines += c == '\n';
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(text.size()));
  state.counters["lines/s"] = benchmark::Counter(static_cast<double>(lines), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["lines"] = static_cast<double>(lines);
}

void run_glslang(benchmark::State& state, const std::string& text,
                 const std::function<bool(glslang::TShader&)>& step) {
  glslang::InitializeProcess();
  for (auto _ : state) {
    glslang::TShader glsl(EShLangFragment);
    const char* source = text.c_str();
    glsl.setStrings(&source, 1);
    if (!step(glsl)) state.SkipWithError(glsl.getInfoLog());
  }
  glslang::FinalizeProcess();
  set_line_counters(state, text);
}

}  // namespace safegi::bench
