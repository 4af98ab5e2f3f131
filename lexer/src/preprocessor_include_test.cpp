#include "preprocessor_test_support.hpp"

namespace safegi::testing {
namespace {

using Includes = PreprocessorTest;

TEST_F(Includes, QuotedIncludesSearchTheIncludingDirectoryFirst) {
  files["shaders/common.glsl"] = "float common_value;\n#include \"sub/deep.glsl\"\n";
  files["shaders/sub/deep.glsl"] = "deep\n";
  files["other/common.glsl"] = "wrong\n";
  options.include_paths = {"other"};
  auto unit = run("#version 330\n#include \"common.glsl\"\nafter\n", "shaders/main.glsl");
  EXPECT_EQ(spell(unit), "float common_value ;\ndeep\nafter");
  ASSERT_EQ(unit.includes.size(), 2u);
  EXPECT_EQ(unit.includes[0].path, "shaders/common.glsl");
  EXPECT_EQ(unit.includes[1].path, "shaders/sub/deep.glsl");
  EXPECT_EQ(unit.tokens[0].range.begin.file, unit.includes[0].file);
  EXPECT_EQ(errors(), "");
}

// Issue 46: an included file that is not text is one error, at its first NUL byte, and is not read.
TEST_F(Includes, AnIncludedFileThatIsNotTextIsOneError) {
  files["image.png"] = std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16) + std::string(5000, '@');
  EXPECT_EQ(output("#include \"image.png\"\nafter\n"), "after");
  EXPECT_EQ(diagnostics.error_count(), 1u);
  EXPECT_EQ(errors(),
            "In file included from main.glsl:1:1:\n"
            "image.png:3:1: error: the file is not text: it holds a NUL byte [E-NOT-TEXT]\n"
            "\\x00\\x00\\x00\n"
            "^~~~\n"
            "help: a shader is text: is this the right file (not an image, an object file or UTF-16)?\n");
}

TEST_F(Includes, AngledIncludesUseOnlySearchPaths) {
  files["lib/safegi/prelude.sgl"] = "dimension length;\n";
  files["prelude.sgl"] = "wrong\n";
  options.include_paths = {"inc", "lib"};
  EXPECT_EQ(output("#include <safegi/prelude.sgl>\n"), "dimension length ;");
  EXPECT_EQ(errors(), "");
}

TEST_F(Includes, MacroNamesTheFile) {
  files["defs.glsl"] = "defs\n";
  files["lib/safegi/prelude.sgl"] = "prelude\n";
  options.include_paths = {"lib"};
  EXPECT_EQ(output("#define DEFS \"defs.glsl\"\n#define PRELUDE <safegi/prelude.sgl>\n"
                   "#include DEFS\n#include PRELUDE\n"),
            "defs\nprelude");
  EXPECT_EQ(errors(), "");
  output("#define NOTHING\n#include NOTHING\n");
  EXPECT_EQ(errors(),
            "main.glsl:2:10: error: expected \"FILENAME\" or <FILENAME> after #include [E-DIRECTIVE]\n"
            "#include NOTHING\n"
            "         ^~~~~~~\n");
}

TEST_F(Includes, MacrosCrossIncludes) {
  files["defs.glsl"] = "#define SCALE 2.0\n#define TWICE(x) (x * SCALE)\n";
  EXPECT_EQ(output("#include \"defs.glsl\"\nTWICE(y)\n"), "( y * 2.0 )");
}

TEST_F(Includes, MissingFile) {
  options.include_paths = {"inc"};
  run("#include \"nowhere.glsl\"\n#include <also_missing.glsl>\n#include\n#include nope\n#include \"\"\n");
  EXPECT_EQ(errors(),
            "main.glsl:1:10: error: 'nowhere.glsl' file not found [E-INCLUDE]\n"
            "#include \"nowhere.glsl\"\n"
            "         ^~~~~~~~~~~~~~\n"
            "help: searched nowhere.glsl, inc/nowhere.glsl\n"
            "main.glsl:2:10: error: 'also_missing.glsl' file not found [E-INCLUDE]\n"
            "#include <also_missing.glsl>\n"
            "         ^~~~~~~~~~~~~~~~~~~\n"
            "help: searched inc/also_missing.glsl\n"
            "main.glsl:3:2: error: expected \"FILENAME\" or <FILENAME> after #include [E-DIRECTIVE]\n"
            "#include\n"
            " ^~~~~~~\n"
            "main.glsl:4:10: error: expected \"FILENAME\" or <FILENAME> after #include [E-DIRECTIVE]\n"
            "#include nope\n"
            "         ^~~~\n"
            "main.glsl:5:10: error: empty file name in #include [E-INCLUDE]\n"
            "#include \"\"\n"
            "         ^~\n");
}

TEST_F(Includes, CycleIsReportedWithTheChain) {
  files["a.glsl"] = "#include \"b.glsl\"\n";
  files["b.glsl"] = "\n#include \"a.glsl\"\n";
  run("#include \"a.glsl\"\n", "main.glsl");
  EXPECT_EQ(errors(),
            "In file included from main.glsl:1:1:\n"
            "In file included from a.glsl:1:1:\n"
            "b.glsl:2:10: error: #include cycle: main.glsl -> a.glsl -> b.glsl -> a.glsl [E-INCLUDE]\n"
            "#include \"a.glsl\"\n"
            "         ^~~~~~~~\n");
}

TEST_F(Includes, ErrorsInIncludedFilesShowTheIncludeChain) {
  files["a.glsl"] = "ok\n@\n";
  run("#version 330\n#include \"a.glsl\"\n");
  EXPECT_EQ(errors(),
            "In file included from main.glsl:2:1:\n"
            "a.glsl:2:1: error: invalid character '@' in program [E-CHARACTER]\n"
            "@\n"
            "^\n");
}

TEST_F(Includes, TheSameFileTwiceGetsTwoFileIds) {
  files["x.glsl"] = "x\n";
  auto unit = run("#include \"x.glsl\"\n#include \"x.glsl\"\n");
  EXPECT_EQ(spell(unit), "x\nx");
  ASSERT_EQ(unit.includes.size(), 2u);
  EXPECT_NE(unit.includes[0].file, unit.includes[1].file);
  EXPECT_EQ(sources.included_from(unit.includes[1].file).begin.line, 2u);
}

TEST_F(Includes, PragmaOnce) {
  files["once.glsl"] = "#pragma once\nonce\n";
  EXPECT_EQ(output("#include \"once.glsl\"\n#include \"once.glsl\"\n"), "once");
}

TEST_F(Includes, IncludeGuards) {
  files["guarded.glsl"] = "#ifndef GUARDED\n#define GUARDED\nbody\n#endif\n";
  EXPECT_EQ(output("#include \"guarded.glsl\"\n#include \"guarded.glsl\"\n"), "body");
}

TEST_F(Includes, UnterminatedConditionalInAnIncludeIsReportedThere) {
  files["open.glsl"] = "#if 1\nopen\n";
  EXPECT_EQ(output("#include \"open.glsl\"\nafter\n#endif\n"), "open\nafter");
  EXPECT_EQ(errors(),
            "In file included from main.glsl:1:1:\n"
            "open.glsl:1:1: error: unterminated conditional directive [E-CONDITIONAL]\n"
            "#if 1\n"
            "^~~~~\n"
            "main.glsl:3:1: error: #endif without #if [E-CONDITIONAL]\n"
            "#endif\n"
            "^~~~~~\n");
}

TEST_F(Includes, VersionInIncludedFile) {
  files["v.glsl"] = "#version 330\n";
  run("#include \"v.glsl\"\n");
  EXPECT_EQ(errors(),
            "In file included from main.glsl:1:1:\n"
            "v.glsl:1:1: error: #version is only allowed in the main file, not in an included file [E-VERSION-DIRECTIVE]\n"
            "#version 330\n"
            "^~~~~~~~~~~~\n");
}

TEST_F(Includes, DepthLimit) {
  files["self.glsl"] = "#include \"self2.glsl\"\n";
  files["self2.glsl"] = "#include \"self3.glsl\"\n";
  files["self3.glsl"] = "x\n";
  options.max_include_depth = 2;
  run("#include \"self.glsl\"\n");
  EXPECT_EQ(errors(),
            "In file included from main.glsl:1:1:\n"
            "In file included from self.glsl:1:1:\n"
            "self2.glsl:1:1: error: #include nested too deeply (limit 2) [E-LIMIT]\n"
            "#include \"self3.glsl\"\n"
            "^~~~~~~~~~~~~~~~~~~~~\n");
}

TEST_F(Includes, FromDisk) {
  options.read_file = nullptr;  // the default reads the file system
  run("#include \"/nonexistent/safegi/x.glsl\"\n");
  EXPECT_EQ(errors(),
            "main.glsl:1:10: error: '/nonexistent/safegi/x.glsl' file not found [E-INCLUDE]\n"
            "#include \"/nonexistent/safegi/x.glsl\"\n"
            "         ^~~~~~~~~~~~~~~~~~~~~~~~~~~~\n"
            "help: searched /nonexistent/safegi/x.glsl\n");
}

}  // namespace
}  // namespace safegi::testing
