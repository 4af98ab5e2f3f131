// The SafeGI annotation syntax (docs/language.md): declarations, annotated
// types everywhere, generics, casts, and the rules that keep annotation words
// ordinary identifiers in plain GLSL.

#include <filesystem>

#include <gtest/gtest.h>

#include <safegi/diagnostics/file.hpp>
#include <safegi/diagnostics/render.hpp>
#include <safegi/lexer/preprocessor.hpp>

#include "test_support.hpp"

namespace safegi::testing {
namespace {

TEST(Annotation, DimensionUnitAndSpaceDeclarations) {
  EXPECT_EQ(dump_first("dimension length;"), "DimensionDecl length base\n");
  EXPECT_EQ(dump_first("dimension radiance = irradiance / (solid_angle * proj);"),
            "DimensionDecl radiance\n  DimBinary /\n    DimName irradiance\n    DimParen\n"
            "      DimBinary *\n        DimName solid_angle\n        DimName proj\n");
  EXPECT_EQ(dump_first("dimension d = length^2 * time^-1 / 1;"),
            "DimensionDecl d\n  DimBinary /\n    DimBinary *\n      DimPower ^2\n        DimName length\n"
            "      DimPower ^-1\n        DimName time\n    DimOne\n");
  EXPECT_EQ(dump_first("unit degree : angle = 3.14159 / 180.0;"),
            "UnitDecl degree\n  DimName angle\n  BinaryExpr /\n    LiteralExpr 3.14159\n    LiteralExpr 180.0\n");
  EXPECT_EQ(dump_first("space world;"), "SpaceDecl world\n");
}

TEST(Annotation, AnnotatedTypesOnEveryKindOfVariable) {
  auto parsed = parse_text(
      "space world; space object; space clip;\n"
      "uniform float<length> radius;\n"
      "in point<world> P;\n"
      "out spectrum<radiance> L[2];\n"
      "layout(std140) uniform Xf { map<object, world> toWorld; rigidmap<world, object> toObject;"
      " projmap<world, clip> proj; };\n"
      "struct Hit { point<world> p; normal<world> n; direction<world> wo; float<length> t; };\n"
      "uniform sampler2D<float<length>> shadowMap;\n"
      "uniform samplerCube<spectrum<radiance>> env;\n"
      "vec3<length> f(vector<world> v, hpoint<clip> h, vec2<1> uv) { float<length / time> s; return v; }\n");
  ASSERT_FALSE(parsed->diagnostics.has_errors()) << parsed->errors();
  std::string dump = parsed->dump();
  for (const char* expected :
       {"TypeSpecifier builtin float\n      Annotation\n        DimName length",
        "TypeSpecifier annotated point\n      Annotation\n        DimName world",
        "TypeSpecifier annotated map\n        Annotation\n          DimName object\n          DimName world",
        "TypeSpecifier builtin sampler2D\n      Annotation\n        TypeSpecifier builtin float\n"
        "          Annotation\n            DimName length",
        "TypeSpecifier builtin samplerCube\n      Annotation\n        TypeSpecifier annotated spectrum",
        "returns: TypeSpecifier builtin vec3\n      Annotation\n        DimName length",
        "ParamDecl v\n      TypeSpecifier annotated vector", "TypeSpecifier builtin vec2\n        Annotation\n          DimOne",
        "Annotation\n              DimBinary /"}) {
    EXPECT_NE(dump.find(expected), std::string::npos) << expected << "\n---\n" << dump;
  }
}

TEST(Annotation, AnnotationRangesCoverTheAngleBrackets) {
  auto parsed = parse_text("uniform sampler2D<float<length>> s;");
  ASSERT_FALSE(parsed->diagnostics.has_errors()) << parsed->errors();
  const auto* decl = ast::dyn_cast<ast::VariableDecl>(parsed->unit().decls.front());
  const ast::Annotation* outer = decl->type->annotation;
  ASSERT_NE(outer, nullptr);
  EXPECT_EQ(outer->range.begin.column, 18u);  // '<'
  EXPECT_EQ(outer->range.end.column, 33u);    // just past the second half of '>>'
  const auto* texel = ast::dyn_cast<ast::TypeSpecifier>(outer->args.front());
  ASSERT_NE(texel, nullptr);
  EXPECT_EQ(texel->annotation->range.begin.column, 24u);
  EXPECT_EQ(texel->annotation->range.end.column, 32u);  // just past the first half of '>>'
}

TEST(Annotation, GenericFunctions) {
  auto generic = parse_text("template<dimension D, space S> float<D> f(point<S> p, float<D> x) { return x; }");
  EXPECT_EQ(dump_ast(*generic->unit().decls.front()).substr(0, 105),
            "FunctionDecl f dimension:D space:S\n  returns: TypeSpecifier builtin float\n    Annotation\n"
            "      DimName D\n");
  auto parsed = parse_text("template<dimension D> spectrum<D> scale(spectrum<D> s, float k);");
  ASSERT_FALSE(parsed->diagnostics.has_errors()) << parsed->errors();
  const auto* fn = ast::dyn_cast<ast::FunctionDecl>(parsed->unit().decls.front());
  EXPECT_EQ(fn->template_range.begin.column, 1u);
  EXPECT_EQ(fn->template_range.end.column, 22u);
}

TEST(Annotation, CastsAreAnnotatedConstructors) {
  EXPECT_EQ(dump_expr("float<solid_angle>(area / (d * d))").substr(0, 107),
            "CallExpr\n  constructor: TypeSpecifier builtin float\n    Annotation\n      DimName solid_angle\n"
            "  BinaryExpr /");
  EXPECT_EQ(dump_expr("point<world>(v)"),
            "CallExpr\n  constructor: TypeSpecifier annotated point\n    Annotation\n      DimName world\n"
            "  IdentifierExpr v\n");
}

TEST(Annotation, AnnotationWordsAreOrdinaryNamesInPlainGlsl) {
  auto parsed = parse_text(
      "uniform float map;\n"
      "struct normal { float x; };\n"
      "float vector(float point) { return point < map ? point : map; }\n"
      "void main() {\n"
      "  float dimension = 1.0, space = 2.0, unit = 3.0;\n"
      "  normal n = normal(1.0);\n"
      "  float spectrum = vector(map);\n"
      "  bool b = map < dimension > bool(space);\n"
      "}\n");
  ASSERT_FALSE(parsed->diagnostics.has_errors()) << parsed->errors();
  EXPECT_EQ(parsed->dump().find("annotated"), std::string::npos) << parsed->dump();
}

TEST(Annotation, VariableNamedLikeATypeWordLeavesItATypeWhereOnlyATypeCanStand) {
  // `in normal<object> normal;` is how real vertex shaders name their input: the word is still a
  // type before a complete annotation and a declarator or '(' (a comparison there would compare a bool).
  auto parsed = parse_text("space world; void f(float point) { bool b = point < 2.0; point<world> p; bool c = point < 1.0 + point; }");
  ASSERT_FALSE(parsed->diagnostics.has_errors()) << parsed->errors();
  std::string dump = parsed->dump();
  EXPECT_NE(dump.find("BinaryExpr <\n              IdentifierExpr point"), std::string::npos) << dump;
  EXPECT_NE(dump.find("TypeSpecifier annotated point"), std::string::npos) << dump;
}

TEST(Annotation, TypeNamedLikeATypeWordShadowsIt) {
  auto parsed = parse_text("struct point { float x; }; void f() { point p; bool b = p.x < 1.0; }");
  ASSERT_FALSE(parsed->diagnostics.has_errors()) << parsed->errors();
  EXPECT_NE(parsed->dump().find("TypeSpecifier named point"), std::string::npos) << parsed->dump();
}

TEST(Annotation, ExpressionThatIsNotAnAnnotation) {
  // `point < a` has no closing '>' so it cannot be an annotation.
  auto parsed = parse_text("void f() { bool b = point < a; }");
  ASSERT_FALSE(parsed->diagnostics.has_errors()) << parsed->errors();
}

TEST(Annotation, StructNamedLikeADeclarationWord) {
  auto parsed = parse_text("struct dimension { float x; }; dimension d; space s;");
  ASSERT_FALSE(parsed->diagnostics.has_errors()) << parsed->errors();
  std::string dump = parsed->dump();
  EXPECT_NE(dump.find("TypeSpecifier named dimension\n    Declarator d"), std::string::npos) << dump;
  EXPECT_NE(dump.find("SpaceDecl s"), std::string::npos) << dump;
}

TEST(Annotation, RationalPowersAreRejected) {
  auto parsed = parse_text("dimension d = length^0.5;");
  EXPECT_EQ(parsed->errors(),
            "test.glsl:1:22: error: dimension exponents must be integers: rational powers are not part of the "
            "language [E-SYNTAX]\ndimension d = length^0.5;\n                     ^~~\n");
}

// `e in target` converts a value to a space or a unit (docs/language.md, "Conversions").
TEST(Annotation, Conversions) {
  EXPECT_EQ(dump_expr("p in world"), "ConvertExpr in\n  IdentifierExpr p\n  DimName world\n");
  // Tighter than `*`, looser than unary operators.
  EXPECT_EQ(dump_expr("a * b in world"),
            "BinaryExpr *\n  IdentifierExpr a\n  ConvertExpr in\n    IdentifierExpr b\n    DimName world\n");
  EXPECT_EQ(dump_expr("-v in world"), "ConvertExpr in\n  UnaryExpr -\n    IdentifierExpr v\n  DimName world\n");
  EXPECT_EQ(dump_expr("d in (kilometer / hour)"),
            "ConvertExpr in\n  IdentifierExpr d\n  DimParen\n    DimBinary /\n      DimName kilometer\n"
            "      DimName hour\n");
  EXPECT_EQ(dump_expr("(p in view) in clip"),
            "ConvertExpr in\n  ParenExpr\n    ConvertExpr in\n      IdentifierExpr p\n      DimName view\n"
            "  DimName clip\n");
  auto power = parse_text("void f() { float x = d in meter^2; }");
  EXPECT_NE(power->errors().find("a power of a unit after 'in' needs parentheses, e.g. x in (meter^2)"), std::string::npos)
      << power->errors();
  // A missing `;` before an `in` declaration is still reported as one.
  auto semicolon = parse_text("float x = 1.0\nin vec3 p;\n");
  EXPECT_NE(semicolon->errors().find("expected ';'"), std::string::npos) << semicolon->errors();
  auto glsl = parse_text("space world; space view; uniform map<world, view> v; void f(point<world> p) { point<view> q = 2.0 * p in view; }");
  ASSERT_EQ(glsl->errors(), "");
  EXPECT_NE(glsl->glsl().find("point<view> q = 2.0 * (p in view);"), std::string::npos) << glsl->glsl();
}

// `float<length in centimeter>`: a dimension measured in a unit.
TEST(Annotation, DimensionsInUnits) {
  EXPECT_EQ(dump_first("uniform float<length in centimeter> r;"),
            "VariableDecl [uniform]\n  TypeSpecifier builtin float\n    Annotation\n      DimUnit in\n        DimName length\n"
            "        DimName centimeter\n  Declarator r\n");
  auto parsed = parse_text("uniform float<area in centimeter^2> a; uniform spectrum<power in kilowatt> p;"
                           " uniform sampler2D<float<length in millimeter>> depth;"
                           " void f() { float<velocity in kilometer / hour> v = float<velocity in kilometer / hour>(1.0); }");
  ASSERT_EQ(parsed->errors(), "");
  EXPECT_NE(parsed->glsl().find("uniform float<area in centimeter^2> a;"), std::string::npos) << parsed->glsl();
  EXPECT_NE(parsed->glsl().find("float<velocity in kilometer / hour>(1.0)"), std::string::npos) << parsed->glsl();
}

// vocabulary.def's entries as the prelude declares them: bases, derived dimensions and their
// synonyms; units and their other spellings (C++'s own units are not the prelude's).
constexpr std::size_t kVocabularyDimensions = 0
#define VOCABULARY_BASE(name) +1
#define VOCABULARY_DIMENSION(name, length, time, energy, angle, solid_angle, proj, shader) +1
#define VOCABULARY_SYNONYM(name, of) +1
#include "safegi/typed/vocabulary.def"
    ;
constexpr std::size_t kVocabularyUnits = 0
#define VOCABULARY_UNIT(name, symbol, dimension, scale) +1
#define VOCABULARY_UNIT_ALIAS(alias, of) +1
#include "safegi/typed/vocabulary.def"
    ;

TEST(Annotation, ThePreludeParses) {
  const std::string text = read_file(SAFEGI_PRELUDE_FILE).value_or("");
  ASSERT_FALSE(text.empty());
  auto parsed = parse_text(text);
  ASSERT_FALSE(parsed->diagnostics.has_errors()) << parsed->errors();
  std::size_t dimensions = 0, units = 0;
  for (const ast::Decl* d : parsed->unit().decls) {
    dimensions += ast::isa<ast::DimensionDecl>(d);
    units += ast::isa<ast::UnitDecl>(d);
  }
  EXPECT_EQ(dimensions, kVocabularyDimensions);
  EXPECT_EQ(units, kVocabularyUnits);
  EXPECT_GT(kVocabularyDimensions, 0u);
  EXPECT_GT(kVocabularyUnits, 0u);
}

TEST(Annotation, ThePreludeLineThroughThePreprocessor) {
  SourceManager sources;
  DiagnosticEngine diagnostics;
  FileId file = sources.add_file("shader.frag",
                                 "#version 330 core\n"
                                 "#include <safegi/prelude.sgl>\n"
                                 "space world;\n"
                                 "uniform spectrum<radiance> L;\n"
                                 "uniform float<length> r = 2.0 * centimeter;\n");
  PreprocessorOptions options;
  options.include_paths.push_back(std::filesystem::path(SAFEGI_PRELUDE_FILE).parent_path().parent_path().string());
  PreprocessedUnit unit = preprocess(sources, file, options, diagnostics);
  ParseResult parsed = parse(unit.tokens, diagnostics);
  ASSERT_FALSE(diagnostics.has_errors()) << render_text(diagnostics.diagnostics(), sources);
  ASSERT_EQ(unit.includes.size(), 1u);
  std::size_t from_prelude = 0;
  for (const ast::Decl* d : parsed.unit->decls) from_prelude += d->range.begin.file == unit.includes[0].file;
  EXPECT_EQ(from_prelude, 61u);  // every prelude declaration, located in the prelude file
  EXPECT_EQ(parsed.unit->decls.size(), 64u);
}

}  // namespace
}  // namespace safegi::testing
