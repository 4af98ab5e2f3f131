// Bad input never crashes, hangs or overflows the stack: limits become
// diagnostics. The random inputs use a fixed seed, so failures reproduce.

#include <random>

#include "preprocessor_test_support.hpp"

namespace safegi::testing {
namespace {

using Robustness = PreprocessorTest;

std::string repeat(std::string_view piece, std::size_t n) {
  std::string out;
  out.reserve(piece.size() * n);
  for (std::size_t i = 0; i < n; ++i) out += piece;
  return out;
}

TEST_F(Robustness, SelfReferenceStops) {
  EXPECT_EQ(output("#define X X + 1\nX\n"), "X + 1");
  EXPECT_EQ(output("#define F(x) F(x) x\nF(F(1))\n"), "F ( F ( 1 ) 1 ) F ( 1 ) 1");
  EXPECT_EQ(errors(), "");
}

TEST_F(Robustness, LongMacroChainHitsTheExpansionDepth) {
  options.max_expansion_depth = 50;
  std::string source;
  for (int i = 0; i < 100; ++i) source += "#define M" + std::to_string(i) + " M" + std::to_string(i + 1) + "\n";
  output(source + "M0\n");
  ASSERT_EQ(diagnostics.error_count(), 1u);
  EXPECT_NE(errors().find("error: macro expansion nested too deeply (limit 50) while expanding 'M50'"),
            std::string::npos)
      << errors();
}

TEST_F(Robustness, ExponentialExpansionHitsTheTokenLimit) {
  options.max_output_tokens = 100000;
  std::string source;
  for (int i = 1; i < 40; ++i) {
    source += "#define X" + std::to_string(i) + " X" + std::to_string(i - 1) + " X" + std::to_string(i - 1) + "\n";
  }
  output(source + "X39\n");
  EXPECT_EQ(diagnostics.error_count(), 1u);
  EXPECT_NE(errors().find("error: preprocessing produces more than 100000 tokens (runaway macro expansion?)"),
            std::string::npos)
      << errors();
}

TEST_F(Robustness, ExponentialArgumentsHitTheTokenLimit) {
  options.max_output_tokens = 100000;
  output("#define D(x) x x\n" + repeat("D(", 40) + "1" + repeat(")", 40) + "\n");
  EXPECT_EQ(diagnostics.error_count(), 1u);
}

TEST_F(Robustness, DeeplyNestedArgumentsAreLimited) {
  output("#define I(x) x\n" + repeat("I(", 1000) + "1" + repeat(")", 1000) + "\n");
  EXPECT_EQ(diagnostics.error_count(), 1u);
  EXPECT_NE(errors().find("nested too deeply (limit 256)"), std::string::npos) << errors();
}

TEST_F(Robustness, DeeplyNestedExpressionsAreLimited) {
  output("#if " + repeat("(", 10000) + "1" + repeat(")", 10000) + "\n#endif\n" + "#if " + repeat("-", 10000) +
         "1\n#endif\n");
  EXPECT_EQ(diagnostics.error_count(), 2u);
  EXPECT_NE(errors().find("error: preprocessor expression nested too deeply"), std::string::npos);
}

TEST_F(Robustness, DeeplyNestedConditionalsAreLimited) {
  options.max_conditional_depth = 100;
  output(repeat("#if 1\n", 200) + repeat("#endif\n", 200));
  EXPECT_NE(errors().find("error: #if nested too deeply (limit 100)"), std::string::npos) << errors();
}

TEST_F(Robustness, SelfIncludeIsACycleNotARecursion) {
  files["main.glsl"] = "#include \"main.glsl\"\n";
  run("#include \"main.glsl\"\n");
  EXPECT_NE(errors().find("#include cycle: main.glsl -> main.glsl"), std::string::npos) << errors();
}

TEST_F(Robustness, IncludeExplosionIsLimited) {
  // Each level includes the next twice: 2^30 inclusions without a limit.
  for (int i = 0; i < 30; ++i) {
    std::string next = "l" + std::to_string(i + 1) + ".glsl";
    files["l" + std::to_string(i) + ".glsl"] = "#include \"" + next + "\"\n#include \"" + next + "\"\n";
  }
  files["l30.glsl"] = "x\n";
  options.max_include_count = 1000;
  run("#include \"l0.glsl\"\n");
  EXPECT_NE(errors().find("more than 1000 #include directives processed"), std::string::npos) << errors();
}

TEST_F(Robustness, HugeSourceIsRefused) {
  options.max_source_bytes = 1000;
  run(std::string(2000, ' '));
  // The line is quoted as its first 157 columns (TextStyle::max_line_columns, "..." included).
  EXPECT_EQ(errors(), "main.glsl:1:1: error: the shader is too large (2000 bytes; limit 1000) [E-LIMIT]\n" + std::string(157, ' ') +
                          "...\n^\n");
}

TEST_F(Robustness, ErrorLimitStopsEarly) {
  DiagnosticEngine limited({.error_limit = 3});
  FileId f = sources.add_file("bad.glsl", repeat("@", 100000));
  preprocess(sources, f, options, limited);
  EXPECT_EQ(limited.error_count(), 3u);
  EXPECT_EQ(limited.diagnostics().size(), 4u);  // and the final "too many errors" note
}

// Random bytes biased towards the characters that matter to a preprocessor.
std::string random_source(std::mt19937& rng, std::size_t size) {
  static constexpr std::string_view kAlphabet =
      "#define if ifdef elif else endif include line version pragma extension error undef defined "
      "()(),,##\n\n\n\\ /* */ // \" < > 0x1 1.5e+3 09 u lf __LINE__ GL_ES A B F(x) x\t@$\x01\xC3\xA9";
  std::string out;
  std::uniform_int_distribution<std::size_t> pick(0, kAlphabet.size() - 1);
  std::uniform_int_distribution<int> byte(0, 255);
  while (out.size() < size) {
    std::size_t at = pick(rng);
    std::size_t len = std::min<std::size_t>(1 + rng() % 8, kAlphabet.size() - at);
    out += kAlphabet.substr(at, len);
    if (rng() % 50 == 0) out += static_cast<char>(byte(rng));
  }
  return out;
}

TEST_F(Robustness, RandomInputsTerminate) {
  std::mt19937 rng(20100621);
  files["inc.glsl"] = "#define INC 1\n#include \"inc.glsl\"\n";
  for (int i = 0; i < 300; ++i) {
    SourceManager local_sources;
    DiagnosticEngine local_diagnostics;
    FileId f = local_sources.add_file("r.glsl", random_source(rng, 1 + rng() % 600));
    PreprocessedUnit unit = preprocess(local_sources, f, options, local_diagnostics);
    ASSERT_FALSE(unit.tokens.empty());
    EXPECT_EQ(unit.tokens.back().kind, TokenKind::eof);
    render_text(local_diagnostics.diagnostics(), local_sources);  // rendering never fails either
    render_json(local_diagnostics.diagnostics(), local_sources);
  }
}

TEST_F(Robustness, MutatedShadersTerminate) {
  const std::string shader =
      "#version 330 core\n#define SQ(x) ((x) * (x))\n#define CAT(a, b) a ## b\n#ifdef GL_core_profile\n"
      "uniform vec3 CAT(light, Pos);\n#else\n#error no\n#endif\n#if SQ(2) == 4 && defined(SQ)\n"
      "float f(float x) { return SQ(x) * 1.5e-3 + 0x1Fu; } /* c */\n#endif\n// end\n";
  std::mt19937 rng(7);
  for (int i = 0; i < 500; ++i) {
    std::string mutated = shader;
    int edits = 1 + static_cast<int>(rng() % 6);
    for (int e = 0; e < edits; ++e) {
      std::size_t at = rng() % mutated.size();
      switch (rng() % 4) {
        case 0: mutated.erase(at, 1 + rng() % 4); break;
        case 1: mutated.insert(at, 1, static_cast<char>(rng() % 256)); break;
        case 2: mutated[at] = "#()\\\n/*\"#,"[rng() % 10]; break;
        default: mutated.insert(at, mutated.substr(rng() % mutated.size(), rng() % 20)); break;
      }
      if (mutated.empty()) mutated = "#";
    }
    SourceManager local_sources;
    DiagnosticEngine local_diagnostics;
    FileId f = local_sources.add_file("m.glsl", mutated);
    PreprocessedUnit unit = preprocess(local_sources, f, options, local_diagnostics);
    EXPECT_EQ(unit.tokens.back().kind, TokenKind::eof);
    render_text(local_diagnostics.diagnostics(), local_sources);
  }
}

}  // namespace
}  // namespace safegi::testing
