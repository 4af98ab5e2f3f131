#pragma once
// glslang as the driver stand-in for tests and benchmarks only (the compiler
// library never links it): does a driver accept the emitted GLSL, and how many
// SPIR-V instructions does it become.

#include <filesystem>
#include <optional>
#include <string>

#include <safegi/typechecker/checker.hpp>

namespace safegi::testing {

struct GlslangVerdict {
  bool accepted = false;
  std::string log;  // glslang's info log when rejected
};

// Parses `glsl` as an OpenGL shader of `stage`. Thread-safe.
GlslangVerdict glslang_validate(const std::string& glsl, Stage stage);

// SPIR-V instruction count of `glsl` (OpenGL client, no optimisation); nullopt
// with `log` set when glslang rejects it.
std::optional<int> spirv_instruction_count(const std::string& glsl, Stage stage, std::string* log = nullptr);

// The bytes of a file; empty when it cannot be read.
std::string read_text_file(const std::filesystem::path& path);

}  // namespace safegi::testing
