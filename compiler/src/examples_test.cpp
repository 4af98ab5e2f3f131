// Dimensions and spaces cost nothing at run time: every annotated example
// shader in examples/shaders compiles (safeglslc, then glslang to SPIR-V) to
// exactly as many instructions as its hand-written plain twin
// (`name.sgl.frag` beside `name.frag`).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "glslang_check.hpp"
#include "safegi/compiler/compile.hpp"

namespace safegi {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> annotated_examples() {
  std::vector<fs::path> out;
  for (const auto& entry : fs::directory_iterator(SAFEGI_EXAMPLE_SHADERS))
    if (entry.path().filename().string().find(".sgl.") != std::string::npos) out.push_back(entry.path());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(Examples, ThereAreAnnotatedExamplesWithPlainTwins) {
  std::vector<fs::path> examples = annotated_examples();
  EXPECT_GE(examples.size(), 4u);
  for (const fs::path& p : examples) {
    std::string twin = p.string();
    twin.replace(twin.find(".sgl."), 5, ".");
    EXPECT_TRUE(fs::exists(twin)) << twin;
  }
}

TEST(Examples, AnnotatedAndPlainCompileToTheSameInstructionCount) {
  for (const fs::path& p : annotated_examples()) {
    SCOPED_TRACE(p.filename().string());
    std::string twin = p.string();
    twin.replace(twin.find(".sgl."), 5, ".");
    CompileResult r = compile({{p.filename().string(), safegi::testing::read_text_file(p)}});
    ASSERT_TRUE(r.success) << r.diagnostics_text();
    const Stage stage = r.stages[0].stage;
    std::string log;
    std::optional<int> annotated = testing::spirv_instruction_count(r.stages[0].glsl, stage, &log);
    ASSERT_TRUE(annotated) << log << r.stages[0].glsl;
    std::optional<int> plain = testing::spirv_instruction_count(safegi::testing::read_text_file(twin), stage, &log);
    ASSERT_TRUE(plain) << log;
    EXPECT_EQ(*annotated, *plain) << "emitted:\n" << r.stages[0].glsl;
    std::cout << p.filename().string() << ": " << *annotated << " SPIR-V instructions, plain twin " << *plain << "\n";
  }
}

}  // namespace
}  // namespace safegi
