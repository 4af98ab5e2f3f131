#pragma once
// Shared by the front-end benchmarks: the generated shaders they read, the
// lines/s counters, and glslang run on the same text in the same process.

#include <functional>
#include <string>

#include <benchmark/benchmark.h>
#include <glslang/Public/ShaderLang.h>

namespace safegi::bench {

// A large, plain GLSL 4.50 fragment shader: `functions` generated functions
// over a struct, a uniform block, macros, loops, switches and swizzles.
std::string plain_shader(int functions);

// A shader that leans on the preprocessor: comments, line continuations,
// object- and function-like macros, token pasting and conditionals.
std::string preprocessor_heavy_shader(int blocks);

// Bytes/s, lines/s and the line count of `text` per iteration.
void set_line_counters(benchmark::State& state, const std::string& text);

// Times `step` on a fresh glslang fragment shader holding `text`, once per
// iteration; a false return skips the benchmark with glslang's log.
void run_glslang(benchmark::State& state, const std::string& text,
                 const std::function<bool(glslang::TShader&)>& step);

}  // namespace safegi::bench
