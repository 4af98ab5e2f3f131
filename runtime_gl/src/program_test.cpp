#include "safegi/runtime_gl/program.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <iostream>

#include "safegi/symbol_table/error.hpp"
#include "test_gl.hpp"

namespace safegi::gl {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;
using testing::example_stage;
using testing::read_testdata;

class ProgramTest : public testing::GlTest {};

std::string replace_line(std::string text, int line, const std::string& replacement) {
  std::size_t begin = 0;
  for (int i = 1; i < line; ++i) begin = text.find('\n', begin) + 1;
  std::size_t end = text.find('\n', begin);
  return text.replace(begin, end - begin, replacement);
}

TEST_F(ProgramTest, LinksTheExampleFromShaderModeTables) {
  Program program = testing::emission_program();
  EXPECT_NE(program.id(), 0u);
  EXPECT_EQ(program.stages().size(), 2u);
}

TEST_F(ProgramTest, LinksTheExampleFromOneProgramModeTable) {
  SymbolTable table = parse_symbol_table(read_testdata("emission.program.json"));
  Program program({{Stage::vertex, read_testdata("emission.vert.glsl"), table},
                   {Stage::fragment, read_testdata("emission.frag.glsl"), table}});
  EXPECT_EQ(program.stages().at(1).file, "emission.sgl.frag");
}

TEST_F(ProgramTest, DriverCompileErrorsPointAtTheAnnotatedSource) {
  ProgramSource fragment = example_stage(Stage::fragment, "emission.frag.glsl", "emission.frag.json");
  fragment.glsl = replace_line(fragment.glsl, 14, "  color = Lx;");
  try {
    Program({example_stage(Stage::vertex, "emission.vert.glsl", "emission.vert.json"), fragment}, "emission");
    FAIL() << "the driver accepted an undeclared identifier";
  } catch (const ShaderError& error) {
    std::cout << error.what() << '\n';
    EXPECT_THAT(error.what(), StartsWith("emission.sgl.frag:14:"));
    EXPECT_THAT(error.what(), HasSubstr("Lx"));
  }
}

TEST_F(ProgramTest, LinkErrorsNameTheProgram) {
  ProgramSource vertex = example_stage(Stage::vertex, "emission.vert.glsl", "emission.vert.json");
  vertex.glsl = replace_line(replace_line(vertex.glsl, 7, "out vec2 Lv;"), 9, "  Lv = vertexLe.xy;");
  try {
    Program({vertex, example_stage(Stage::fragment, "emission.frag.glsl", "emission.frag.json")}, "emission");
    FAIL() << "the driver linked a vec2 output to a vec3 input";
  } catch (const ShaderError& error) {
    std::cout << error.what() << '\n';
    EXPECT_THAT(error.what(), StartsWith("emission: error: the driver could not link the program:\n"));
  }
}

TEST_F(ProgramTest, ATableWithoutTheStageIsRejected) {
  try {
    Program({example_stage(Stage::vertex, "emission.vert.glsl", "emission.frag.json")}, "emission");
    FAIL();
  } catch (const ShaderError& error) {
    EXPECT_STREQ(error.what(),
                 "emission: error: the symbol table given for the vertex stage has no entry for it");
  }
}

// A stage checked as Vulkan GLSL binds by descriptor sets and push constants,
// which an OpenGL program has not: refused before the driver sees it.
TEST_F(ProgramTest, AStageCompiledForVulkanIsRejected) {
  ProgramSource fragment = example_stage(Stage::fragment, "emission.frag.glsl", "emission.frag.json");
  fragment.symbols.stages.at(0).client = Client::vulkan;
  try {
    Program({example_stage(Stage::vertex, "emission.vert.glsl", "emission.vert.json"), fragment}, "emission");
    FAIL();
  } catch (const ShaderError& error) {
    EXPECT_STREQ(error.what(),
                 "emission: error: the fragment stage was compiled for Vulkan (-V or --target-env vulkan*: descriptor "
                 "sets, push constants); for OpenGL compile it without -V, or to SPIR-V with -G");
  }
}

}  // namespace
}  // namespace safegi::gl
