// safegi_add_shaders() ran at build time for this test binary (see
// CMakeLists.txt): its outputs exist, are plain GLSL a driver accepts and a
// program-mode symbol table the runtime can read.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "glslang_check.hpp"
#include "safegi/symbol_table/symbol_table.hpp"

namespace safegi {
namespace {

TEST(SafegiAddShaders, WritesGlslADriverAcceptsAndOneProgramTable) {
  const std::string dir = SAFEGI_GENERATED_SHADERS;
  for (auto [name, stage] : {std::pair{"tint.vert.glsl", Stage::vertex}, std::pair{"tint.frag.glsl", Stage::fragment}}) {
    const std::string glsl = safegi::testing::read_text_file(dir + "/" + name);
    ASSERT_FALSE(glsl.empty()) << name;
    EXPECT_EQ(glsl.find('<'), std::string::npos) << glsl;
    testing::GlslangVerdict verdict = testing::glslang_validate(glsl, stage);
    EXPECT_TRUE(verdict.accepted) << verdict.log << glsl;
  }
  gl::SymbolTable table = gl::parse_symbol_table(safegi::testing::read_text_file(dir + "/safegi_compiler_test.json"), "generated");
  EXPECT_EQ(table.mode, gl::TableMode::program);
  ASSERT_EQ(table.stages.size(), 2u);
  ASSERT_NE(table.stage(gl::Stage::vertex), nullptr);
  EXPECT_NE(table.stage(gl::Stage::vertex)->find(gl::Storage::uniform, "worldFromObject"), nullptr);
  // The depfile (safeglslc -MD) that makes the build track #include'd files.
  const std::string depfile = safegi::testing::read_text_file(dir + "/safegi_compiler_test.json.d");
  EXPECT_EQ(depfile.rfind(dir + "/tint.vert.glsl:", 0), 0u) << depfile;  // the rule's first output
  EXPECT_NE(depfile.find("tint.sgl.frag"), std::string::npos) << depfile;
}

}  // namespace
}  // namespace safegi
