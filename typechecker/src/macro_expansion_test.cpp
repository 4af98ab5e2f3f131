// Diagnostics inside macro expansions carry their "in expansion of macro X"
// notes (CheckOptions::tokens / sources; src/expansions.hpp).

#include <gtest/gtest.h>

#include <safegi/diagnostics/render.hpp>
#include <safegi/lexer/preprocessor.hpp>
#include <safegi/parser/parser.hpp>

#include "safegi/typechecker/checker.hpp"

namespace safegi {
namespace {

std::string preprocess_and_check(const std::string& source) {
  SourceManager sources;
  DiagnosticEngine diagnostics;
  FileId file = sources.add_file("m.frag", source);
  PreprocessedUnit unit = preprocess(sources, file, {}, diagnostics);
  ParseResult parsed = parse(unit.tokens, diagnostics);
  CheckOptions options;
  options.stage = Stage::fragment;
  options.tokens = &unit.tokens;
  options.sources = &sources;
  check(*parsed.unit, options, diagnostics);
  return render_text(diagnostics.diagnostics(), sources);
}

TEST(MacroExpansion, ErrorInsideAMacroBodyNamesTheExpansion) {
  EXPECT_EQ(preprocess_and_check("dimension length;\n"
                                 "dimension time;\n"
                                 "#define SUM(a, b) (a + b)\n"
                                 "uniform float<length> d;\n"
                                 "uniform float<time> t;\n"
                                 "out vec4 c;\n"
                                 "void main() {\n"
                                 "  float<length> ok = SUM(d, d);\n"
                                 "  c = vec4(SUM(d, t));\n"
                                 "}\n"),
            "m.frag:3:22: error: cannot add float<length> and float<time> [E-DIMENSION-MISMATCH]\n"
            "#define SUM(a, b) (a + b)\n"
            "                     ^\n"
            "m.frag:9:12: note: in expansion of macro 'SUM' (defined at m.frag:3:9)\n"
            "  c = vec4(SUM(d, t));\n"
            "           ^~~~~~~~~\n"
            "help: time where length is expected: a different quantity, not a missing factor (another variable meant?)\n"
            "m.frag:4:23: note: 'd' declared here as float<length>\n"
            "uniform float<length> d;\n"
            "                      ^\n"
            "m.frag:5:21: note: 't' declared here as float<time>\n"
            "uniform float<time> t;\n"
            "                    ^\n");
}

TEST(MacroExpansion, ErrorOutsideMacrosHasNoNote) {
  EXPECT_EQ(preprocess_and_check("void main() { float x = 1.0; int i = x; }\n"),
            "m.frag:1:38: error: cannot initialize 'i' of type int with a value of type float<1> [E-TYPE-MISMATCH]\n"
            "void main() { float x = 1.0; int i = x; }\n"
            "                                 ~   ^\n"
            "m.frag:1:34: note: 'i' declared here\n"
            "void main() { float x = 1.0; int i = x; }\n"
            "                                 ^\n"
            "m.frag:1:25: note: type of 'x' inferred from its initializer as float<1>\n"
            "void main() { float x = 1.0; int i = x; }\n"
            "                        ^~~\n");
}

}  // namespace
}  // namespace safegi
