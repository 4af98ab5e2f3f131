// CheckOptions::record_symbols: every declaration and use of a name, with
// where it is declared and its type in the program's words.

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace safegi::testing {
namespace {

// "kind name @line:col -> line:col : type_text" for every occurrence in test.frag.
std::vector<std::string> occurrences(const CheckedSource& c) {
  std::vector<std::string> out;
  for (const SymbolOccurrence& o : c.result.symbols) {
    if (c.sources.path(o.range.begin.file) != "test.frag") continue;
    std::string line = std::string(symbol_kind_name(o.kind)) + " " + o.name + " @" + std::to_string(o.range.begin.line) +
                       ":" + std::to_string(o.range.begin.column) + (o.is_declaration ? " decl" : "");
    if (o.declaration.valid()) {
      const std::string file = c.sources.path(o.declaration.begin.file);
      line += " -> " + (file == "test.frag" ? "" : file + ":") + std::to_string(o.declaration.begin.line) + ":" +
              std::to_string(o.declaration.begin.column);
    }
    if (!o.type_text.empty()) line += " : " + o.type_text;
    out.push_back(line);
  }
  return out;
}

TEST(Symbols, OffByDefault) {
  auto c = check_source("space world;\nuniform point<world> p;\n");
  EXPECT_TRUE(c->result.symbols.empty());
}

TEST(Symbols, VariablesAnnotationsAndTheirDeclarations) {
  auto c = check_source(R"(space world;
uniform point<world> lightPos;
in point<world> P;
void main() {
  vector<world> toLight = lightPos - P;
  float<length> d = length(toLight) + 2.0 * centimeter;
  float c = d;
}
)", {.symbols = true});
  ASSERT_EQ(c->rendered(), "");
  const std::vector<std::string> expected = {
      "space world @1:7 decl -> 1:7",
      "space world @2:15 -> 1:7",
      "variable lightPos @2:22 decl -> 2:22 : point<world>",
      "space world @3:10 -> 1:7",
      "variable P @3:17 decl -> 3:17 : point<world>",
      "function main @4:6 decl -> 4:6 : void main()",
      "space world @5:10 -> 1:7",
      "variable lightPos @5:27 -> 2:22 : point<world>",
      "variable P @5:38 -> 3:17 : point<world>",
      "variable toLight @5:17 decl -> 5:17 : vector<world>",
      "dimension length @6:9 -> prelude.sgl:8:11 : float<length>",
      "variable toLight @6:28 -> 5:17 : vector<world>",
      "built-in function length @6:21 : length: geo<S, D> -> float<D>",
      "unit centimeter @6:45 -> prelude.sgl:41:6 : float<length>",
      "variable d @6:17 decl -> 6:17 : float<length>",
      "variable d @7:13 -> 6:17 : float<length>",
      "variable c @7:9 decl -> 7:9 : float<length>",  // inferred from its initialiser
  };
  EXPECT_EQ(occurrences(*c), expected);
}

TEST(Symbols, FunctionsTemplatesStructsAndFields) {
  auto c = check_source(R"(struct Light { spectrum<intensity> I; float<length> r; };
uniform Light light;
template<dimension D>
spectrum<D> attenuate(spectrum<D> x, float<1> v) { return x * v; }
void main() {
  spectrum<intensity> I = attenuate(light.I, 0.5);
  gl_FragDepth = 0.0;
}
)", {.symbols = true});
  ASSERT_EQ(c->rendered(), "");
  const std::vector<std::string> expected = {
      "dimension intensity @1:25 -> prelude.sgl:21:11 : float<intensity>",
      "dimension length @1:45 -> prelude.sgl:8:11 : float<length>",
      "struct Light @1:8 decl -> 1:8 : struct Light",
      "field I @1:36 decl -> 1:36 : spectrum<intensity>",
      "field r @1:53 decl -> 1:53 : float<length>",
      "struct Light @2:9 -> 1:8 : struct Light",
      "variable light @2:15 decl -> 2:15 : Light",
      "dimension parameter D @3:20 decl -> 3:20",
      "dimension parameter D @4:10 -> 3:20",
      "dimension parameter D @4:32 -> 3:20",
      "function attenuate @4:13 decl -> 4:13 : template<dimension D> spectrum<D> attenuate(spectrum<D> x, float<dimensionless> v)",
      "variable x @4:35 decl -> 4:35 : spectrum<D>",
      "variable v @4:47 decl -> 4:47 : float<dimensionless>",
      "variable x @4:59 -> 4:35 : spectrum<D>",
      "variable v @4:63 -> 4:47 : float<dimensionless>",
      "function main @5:6 decl -> 5:6 : void main()",
      "dimension intensity @6:12 -> prelude.sgl:21:11 : float<intensity>",
      "variable light @6:37 -> 2:15 : Light",
      "field I @6:43 -> 1:36 : spectrum<intensity>",
      "function attenuate @6:27 -> 4:13 : template<dimension D> spectrum<D> attenuate(spectrum<D> x, float<dimensionless> v)",
      "variable I @6:23 decl -> 6:23 : spectrum<intensity>",
      "built-in variable gl_FragDepth @7:3 : float",
  };
  EXPECT_EQ(occurrences(*c), expected);
  // The call's occurrence has the result unification gave it, not the generic one.
  for (const SymbolOccurrence& o : c->result.symbols)
    if (o.kind == SymbolKind::function && !o.is_declaration) {
      EXPECT_EQ(c->result.describe(o.type), "spectrum<intensity>");
    }
}

TEST(Symbols, ACallWithATypeErrorStillNamesItsFunction) {
  auto c = check_source(R"(float<length> twice(float<length> x) { return 2.0 * x; }
void main() { float<length> y = twice(float<time>(1.0)); }
)", {.symbols = true});
  ASSERT_EQ(c->errors(), 1u);
  bool found = false;
  for (const SymbolOccurrence& o : c->result.symbols)
    if (o.kind == SymbolKind::function && !o.is_declaration) {
      found = true;
      EXPECT_EQ(o.declaration.begin.line, 1u);
      EXPECT_EQ(o.type_text, "float<length> twice(float<length> x)");
    }
  EXPECT_TRUE(found);
}

TEST(Symbols, PreludeDeclarationsResolveTheirOwnUses) {
  auto c = check_source("void main() {}\n", {.symbols = true});
  // radiance = irradiance / (solid_angle * proj): the use of irradiance points at its declaration.
  bool found = false;
  for (const SymbolOccurrence& o : c->result.symbols)
    if (o.name == "irradiance" && !o.is_declaration) {
      found = true;
      ASSERT_TRUE(o.declaration.valid());
      EXPECT_EQ(c->sources.line_text(o.declaration.begin.file, o.declaration.begin.line), "dimension irradiance = power / area;");
    }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace safegi::testing
