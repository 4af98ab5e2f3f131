// The safeglslc command in-process: what the golden cases cannot express
// (no input at all, --help) and the file outputs.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include <safegi/diagnostics/file.hpp>

#include "safegi/compiler/cli.hpp"

namespace safegi {
namespace {

struct CliRun {
  int status = 0;
  std::string out, err;
};

CliRun run(std::vector<std::string> args, const std::string& stdin_text = {}) {
  std::istringstream in(stdin_text);
  std::ostringstream out, err;
  CliStreams io{in, out, err, false};
  CliRun r;
  r.status = run_safeglslc(args, io);
  r.out = out.str();
  r.err = err.str();
  return r;
}

TEST(Safeglslc, NoInputIsAUsageError) {
  CliRun r = run({});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("files is required"), std::string::npos) << r.err;
}

TEST(Safeglslc, HelpListsTheFlags) {
  CliRun r = run({"--help"});
  EXPECT_EQ(r.status, 0);
  for (const char* flag : {"-S", "-o", "--symbols", "-I", "-D", "-U", "--Werror", "--error-limit", "--diagnostics-format", "--version",
                           "-d", "--glsl-version", "--client", "--target-env", "--aml", "--amb", "-R", "-g"})
    EXPECT_NE(r.out.find(flag), std::string::npos) << flag;
}

TEST(Safeglslc, ExplainPrintsWhatACodeMeans) {
  CliRun r = run({"--explain", "E-UNIT-CAST"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("E-UNIT-CAST: a cast that would change the unit of a quantity", 0), 0u) << r.out;
  CliRun unknown = run({"--explain", "E-DIM-MISMATCH"});
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.err.find("'E-DIM-MISMATCH' is no diagnostic code"), std::string::npos) << unknown.err;
  EXPECT_NE(run({"--help"}).out.find("--explain"), std::string::npos);
}

TEST(Safeglslc, WritesGlslAndSymbolsFiles) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "safeglslc_cli_test";
  std::filesystem::create_directories(dir);
  const std::string glsl = (dir / "out.frag.glsl").string(), json = (dir / "out.json").string();
  CliRun r = run({"-", "-S", "frag", "-o", glsl, "--symbols", json},
              "#version 330 core\n#include <safegi/prelude.sgl>\nuniform float<length> d;\nout vec4 c;\nvoid main() { c = vec4(d); }\n");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string gs = read_file(glsl).value_or(""), js = read_file(json).value_or("");
  EXPECT_NE(gs.find("uniform float         d;"), std::string::npos) << gs;
  EXPECT_NE(js.find("\"name\": \"d\""), std::string::npos) << js;
  std::filesystem::remove_all(dir);
}

TEST(Safeglslc, WritesAMakeStyleDepfile) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "safeglslc_depfile_test";
  std::filesystem::create_directories(dir / "my lib");
  const std::string shader = (dir / "a.sgl.frag").string(), header = (dir / "my lib" / "common.sgl").string();
  std::ofstream(header) << "float<length> twice(float<length> x) { return 2.0 * x; }\n";
  std::ofstream(shader) << "#version 330 core\n#include <safegi/prelude.sgl>\n#include \"my lib/common.sgl\"\n"
                           "uniform float<length> d;\nout vec4 c;\nvoid main() { c = vec4(twice(d)); }\n";
  const std::string glsl = (dir / "a.frag.glsl").string();
  CliRun r = run({shader, "-o", glsl, "-MD"});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string depfile = read_file(glsl + ".d").value_or("");
  std::string escaped_header = header;
  escaped_header.replace(escaped_header.find("my lib"), 6, "my\\ lib");
  EXPECT_EQ(depfile, glsl + ": \\\n  " + shader + " \\\n  " + escaped_header + "\n");
  // -MF names the file; without an output file there is no target to name.
  r = run({shader, "-o", glsl, "-MD", "-MF", (dir / "deps.d").string()});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "deps.d"));
  r = run({shader, "-MD"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "safeglslc: error: -MD needs an output file (-o or --symbols) to name as the depfile's target [E-COMMAND-LINE]\n");
  std::filesystem::remove_all(dir);
}

TEST(Safeglslc, UnwritableOutputIsAnIoError) {
  CliRun r = run({"-", "-S", "frag", "-o", "/nonexistent-dir/x.glsl"}, "#version 330 core\nvoid main() {}\n");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("cannot write"), std::string::npos) << r.err;
}

// Issue 46: what a file of garbage costs. Counts and messages here; the times are in docs/safeglslc.md.
std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(Safeglslc, StopsAfterTwentyErrorsByDefault) {
  std::string shader = "#version 330 core\nvoid main() {\n";
  for (int i = 0; i < 50; ++i) shader += "  a" + std::to_string(i) + " = 1;\n";
  shader += "}\n";
  CliRun r = run({"-", "-S", "frag"}, shader);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(count_of(r.err, ": error: "), 20u) << r.err;
  EXPECT_NE(r.err.find("note: too many errors emitted, stopping now (error limit 20)\n20 errors generated.\n"), std::string::npos)
      << r.err;
  r = run({"-", "-S", "frag", "-ferror-limit=0"}, shader);
  EXPECT_EQ(count_of(r.err, ": error: "), 50u);
  EXPECT_EQ(r.err.find("too many errors"), std::string::npos);
}

TEST(Safeglslc, RefusesInputThatIsNotTextWithOneError) {
  std::mt19937 rng(46);
  std::string bytes(3 << 20, '\0');
  for (char& c : bytes) c = static_cast<char>(rng() & 0xFF);
  CliRun r = run({"-", "-S", "frag"}, bytes);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(count_of(r.err, ": error: "), 1u) << r.err.substr(0, 2000);
  EXPECT_EQ(r.err.rfind("<stdin>:1:", 0), 0u) << r.err.substr(0, 2000);
  EXPECT_NE(r.err.find("error: the file is not text: it holds a NUL byte [E-NOT-TEXT]"), std::string::npos)
      << r.err.substr(0, 2000);
  // No NUL byte, but control characters as a binary file has them.
  std::string controls = "#version 330 core\n";
  for (int i = 0; i < 400; ++i) controls += "\x01\x02\x1b x";
  r = run({"-", "-S", "frag"}, controls);
  EXPECT_EQ(count_of(r.err, ": error: "), 1u) << r.err;
  EXPECT_NE(r.err.find("<stdin>:2:1: error: the file is not text: 1200 of its first 2018 bytes are control characters [E-NOT-TEXT]"),
            std::string::npos)
      << r.err;
  // Text with a few of them is still text: each is the lexer's error.
  r = run({"-", "-S", "frag"}, "#version 330 core\n\x01 out vec4 c;\nvoid main() { c = vec4(1.0); }\n");
  EXPECT_EQ(r.err.find("E-NOT-TEXT"), std::string::npos) << r.err;
}

TEST(Safeglslc, QuotesAWindowOfAVeryLongLine) {
  std::string shader = "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0);";
  for (int i = 0; i < 20000; ++i) shader += " x" + std::to_string(i) + " = 1;";
  shader += " }\n";
  CliRun r = run({"-", "-S", "frag", "--error-limit", "0"}, shader);
  EXPECT_EQ(count_of(r.err, ": error: "), 20000u);
  std::istringstream lines(r.err);
  std::size_t longest = 0;
  for (std::string line; std::getline(lines, line);) longest = std::max(longest, line.size());
  EXPECT_LE(longest, 166u);  // the header line; every quoted line is at most 160 columns and its "..." marks
  EXPECT_NE(r.err.find(" x19999 = 1; }\n"), std::string::npos);
  EXPECT_NE(r.err.find("\n..."), std::string::npos);
}

// The environment and the output form are independent: --target-env vulkan1.2 with a GLSL-named
// output checks Vulkan GLSL and writes it plain (this test's safeglslc has no SPIR-V backend);
// .spv names, or none, ask for SPIR-V as glslangValidator's --target-env does.
TEST(Safeglslc, TargetEnvironmentWithAGlslOutputWritesPlainVulkanGlsl) {
  const std::string vulkan =
      "#version 450\nlayout(location = 0) out vec4 c;\nvoid main() { c = vec4(float(gl_VertexIndex)); gl_Position = c; }\n";
  CliRun plain = run({"-", "-S", "vert", "--target-env", "vulkan1.2", "-o", "-"}, vulkan);
  EXPECT_EQ(plain.status, 0) << plain.err;
  EXPECT_NE(plain.out.find("gl_VertexIndex"), std::string::npos) << plain.out;
  CliRun gl = run({"-", "-S", "vert", "-o", "-"}, vulkan);
  EXPECT_NE(gl.status, 0);
  EXPECT_NE(gl.err.find("gl_VertexIndex"), std::string::npos) << gl.err;
  EXPECT_TRUE(wants_spirv({"x.vert", "--target-env", "vulkan1.2"}));
  EXPECT_TRUE(wants_spirv({"x.vert", "--target-env", "vulkan1.2", "-o", "x.spv"}));
  EXPECT_FALSE(wants_spirv({"x.vert", "--target-env", "vulkan1.2", "-o", "x.vert.glsl"}));
  EXPECT_TRUE(wants_spirv({"x.vert", "-V", "-o", "x.vert.glsl"}));
  CliRun mixed = run({"a.vert", "b.frag", "--target-env", "vulkan1.2", "-o", "a.spv", "-o", "b.frag.glsl"});
  EXPECT_EQ(mixed.status, 2);
  EXPECT_NE(mixed.err.find("some -o outputs are named .spv and some are not"), std::string::npos) << mixed.err;
}

}  // namespace
}  // namespace safegi
