// Declarations: qualifiers, layout, structs, interface blocks, arrays,
// functions, precision, subroutines.

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace safegi::testing {
namespace {

TEST(ParseDecl, QualifiersInOrder) {
  EXPECT_EQ(dump_first("layout(location = 2, component = 1, binding = 1 + 2) flat centroid in highp vec3 n;"),
            "VariableDecl [layout(location = 2, component = 1, binding = 1 + 2)] [flat] [centroid] [in] [highp]\n"
            "  TypeSpecifier builtin vec3\n  Declarator n\n");
  EXPECT_EQ(dump_first("invariant precise noperspective sample out float a;"),
            "VariableDecl [invariant] [precise] [noperspective] [sample] [out]\n"
            "  TypeSpecifier builtin float\n  Declarator a\n");
  EXPECT_EQ(dump_first("layout(rgba8) coherent volatile restrict readonly writeonly uniform image2D img;"),
            "VariableDecl [layout(rgba8)] [coherent] [volatile] [restrict] [readonly] [writeonly] [uniform]\n"
            "  TypeSpecifier builtin image2D\n  Declarator img\n");
}

TEST(ParseDecl, LayoutAcceptsKeywordsAsIdentifiers) {
  EXPECT_EQ(dump_first("layout(shared, row_major) uniform;"), "QualifierDecl [layout(shared, row_major)] [uniform]\n");
  EXPECT_EQ(dump_first("layout(local_size_x = 8, local_size_y = 8) in;"),
            "QualifierDecl [layout(local_size_x = 8, local_size_y = 8)] [in]\n");
}

TEST(ParseDecl, QualifierOnlyDeclarations) {
  EXPECT_EQ(dump_first("invariant gl_Position, v;"), "QualifierDecl [invariant] gl_Position v\n");
  EXPECT_EQ(dump_first("precise out p;"), "QualifierDecl [precise] [out] p\n");
}

TEST(ParseDecl, MultipleDeclaratorsArraysAndInitialisers) {
  EXPECT_EQ(dump_first("const float a = 1.0, b[2][3], c[] = float[](1.0);"),
            "VariableDecl [const]\n  TypeSpecifier builtin float\n  Declarator a\n    init: LiteralExpr 1.0\n"
            "  Declarator b\n    ArrayDim\n      LiteralExpr 2\n    ArrayDim\n      LiteralExpr 3\n"
            "  Declarator c\n    ArrayDim unsized\n    init: CallExpr\n"
            "      constructor: TypeSpecifier builtin float\n        ArrayDim unsized\n      LiteralExpr 1.0\n");
  EXPECT_EQ(dump_first("vec4[2] pair;"),
            "VariableDecl\n  TypeSpecifier builtin vec4\n    ArrayDim\n      LiteralExpr 2\n  Declarator pair\n");
}

TEST(ParseDecl, StructsNamedAnonymousAndNested) {
  EXPECT_EQ(dump_first("struct Light { vec3 p; float r[2]; } lights[4];"),
            "VariableDecl\n  TypeSpecifier struct Light\n    StructDecl Light\n"
            "      VariableDecl\n        TypeSpecifier builtin vec3\n        Declarator p\n"
            "      VariableDecl\n        TypeSpecifier builtin float\n        Declarator r\n"
            "          ArrayDim\n            LiteralExpr 2\n"
            "  Declarator lights\n    ArrayDim\n      LiteralExpr 4\n");
  EXPECT_EQ(dump_first("struct { struct Inner { int i; } in1; } s;"),
            "VariableDecl\n  TypeSpecifier struct\n    StructDecl\n      VariableDecl\n"
            "        TypeSpecifier struct Inner\n          StructDecl Inner\n            VariableDecl\n"
            "              TypeSpecifier builtin int\n              Declarator i\n        Declarator in1\n"
            "  Declarator s\n");
  auto parsed = parse_text("struct S { float x; }; S a; S b[2]; void f() { S c = S(1.0); S[2] d; }");
  EXPECT_FALSE(parsed->diagnostics.has_errors()) << parsed->errors();
}

TEST(ParseDecl, InterfaceBlocks) {
  EXPECT_EQ(dump_first("layout(std140, binding = 0) uniform Camera { mat4 view; layout(offset = 64) mat4 proj; } cam[2];"),
            "InterfaceBlockDecl Camera instance=cam [layout(std140, binding = 0)] [uniform]\n"
            "  VariableDecl\n    TypeSpecifier builtin mat4\n    Declarator view\n"
            "  VariableDecl [layout(offset = 64)]\n    TypeSpecifier builtin mat4\n    Declarator proj\n"
            "  ArrayDim\n    LiteralExpr 2\n");
  EXPECT_EQ(dump_first("buffer Data { readonly float values[]; };"),
            "InterfaceBlockDecl Data [buffer]\n  VariableDecl [readonly]\n    TypeSpecifier builtin float\n"
            "    Declarator values\n      ArrayDim unsized\n");
  EXPECT_EQ(dump_first("out VertexData { smooth vec3 n; } vd;"),
            "InterfaceBlockDecl VertexData instance=vd [out]\n  VariableDecl [smooth]\n"
            "    TypeSpecifier builtin vec3\n    Declarator n\n");
}

TEST(ParseDecl, FunctionsAndPrototypes) {
  EXPECT_EQ(dump_first("highp float f(const in float x, out vec3 y[2], sampler2D);"),
            "FunctionDecl f prototype [highp]\n  returns: TypeSpecifier builtin float\n"
            "  ParamDecl x [const] [in]\n    TypeSpecifier builtin float\n"
            "  ParamDecl y [out]\n    TypeSpecifier builtin vec3\n    ArrayDim\n      LiteralExpr 2\n"
            "  ParamDecl\n    TypeSpecifier builtin sampler2D\n");
  EXPECT_EQ(dump_first("void main(void) {}"),
            "FunctionDecl main (void)\n  returns: TypeSpecifier builtin void\n  CompoundStmt\n");
  auto parsed = parse_text("float[2] g() { return float[2](1.0, 2.0); }");
  EXPECT_EQ(parsed->dump().substr(0, 111),
            "TranslationUnit\n  FunctionDecl g\n    returns: TypeSpecifier builtin float\n      ArrayDim\n"
            "        LiteralExpr 2\n");
}

TEST(ParseDecl, PrecisionStatements) {
  EXPECT_EQ(dump_first("precision mediump float;"), "PrecisionDecl mediump\n  TypeSpecifier builtin float\n");
  EXPECT_EQ(dump_first("void f() { precision highp int; }"), "DeclStmt\n  PrecisionDecl highp\n    TypeSpecifier builtin int\n");
}

TEST(ParseDecl, Subroutines) {
  auto parsed = parse_text(
      "subroutine vec4 colorRed_t(float x);\n"
      "subroutine (colorRed_t) vec4 ColorRed(float x) { return vec4(x); }\n"
      "subroutine uniform colorRed_t myRedFunc;\n"
      "layout(location = 0) subroutine uniform colorRed_t other[2];\n");
  ASSERT_FALSE(parsed->diagnostics.has_errors()) << parsed->errors();
  std::string dump = parsed->dump();
  EXPECT_NE(dump.find("FunctionDecl colorRed_t prototype [subroutine]"), std::string::npos) << dump;
  EXPECT_NE(dump.find("FunctionDecl ColorRed [subroutine(colorRed_t)]"), std::string::npos) << dump;
  EXPECT_NE(dump.find("VariableDecl [subroutine] [uniform]\n    TypeSpecifier named colorRed_t"), std::string::npos)
      << dump;
}

TEST(ParseDecl, SubroutineArrayElementCall) {
  EXPECT_EQ(dump_first("void f() { shade[1](n); }"),
            "ExprStmt\n  CallExpr\n    callee: IndexExpr\n      IdentifierExpr shade\n      LiteralExpr 1\n"
            "    IdentifierExpr n\n");
}

TEST(ParseDecl, UnknownTypeNameIsReportedOnceAndParsingGoesOn) {
  auto parsed = parse_text("B x[1];\nvoid f(B y);\ngl_LightSourceParameters light;\n");
  EXPECT_EQ(parsed->errors(),
            "test.glsl:1:1: error: unknown type name 'B' [E-UNKNOWN-TYPE]\nB x[1];\n^\n"
            "test.glsl:2:8: error: unknown type name 'B' [E-UNKNOWN-TYPE]\nvoid f(B y);\n       ^\n");
  EXPECT_EQ(parsed->unit().decls.size(), 3u);
}

TEST(ParseDecl, GlobalStraySemicolons) {
  auto parsed = parse_text("float a;; void f() {};");
  ASSERT_FALSE(parsed->diagnostics.has_errors()) << parsed->errors();
  EXPECT_EQ(parsed->unit().decls.size(), 4u);
}

TEST(ParseDecl, DeclarationRangesAndNameRanges) {
  auto parsed = parse_text("uniform vec3 color;");
  const auto* decl = ast::dyn_cast<ast::VariableDecl>(parsed->unit().decls.front());
  ASSERT_NE(decl, nullptr);
  EXPECT_EQ(decl->range.begin.column, 1u);
  EXPECT_EQ(decl->range.end.column, 20u);
  EXPECT_EQ(decl->declarators[0].name_range.begin.column, 14u);
  EXPECT_EQ(decl->type->name_range.begin.column, 9u);
}

TEST(ParseDecl, ArraysOfArraysNeedVersion430OrTheirExtension) {
  ParseOptions options;
  options.language = LanguageLevel{330, false, {}};
  auto parsed = parse_text("float a[2][3];\nfloat[2] b[3];\nstruct S { vec2 m[1][2]; };\nvoid f(int p[2][2]);\n"
                           "float c[4];\nfloat[5] d;\n",
                           options);
  EXPECT_EQ(parsed->errors(),
            "test.glsl:1:11: error: arrays of arrays require #version 430 or GL_ARB_arrays_of_arrays [E-VERSION]\n"
            "float a[2][3];\n"
            "          ^~~\n"
            "test.glsl:2:11: error: arrays of arrays require #version 430 or GL_ARB_arrays_of_arrays [E-VERSION]\n"
            "float[2] b[3];\n"
            "          ^~~\n"
            "test.glsl:3:21: error: arrays of arrays require #version 430 or GL_ARB_arrays_of_arrays [E-VERSION]\n"
            "struct S { vec2 m[1][2]; };\n"
            "                    ^~~\n"
            "test.glsl:4:16: error: arrays of arrays require #version 430 or GL_ARB_arrays_of_arrays [E-VERSION]\n"
            "void f(int p[2][2]);\n"
            "               ^~~\n");
  options.language->extensions = {"GL_ARB_arrays_of_arrays"};
  EXPECT_EQ(parse_text("float a[2][3];\n", options)->errors(), "");
  options.language = LanguageLevel{310, true, {}};
  EXPECT_EQ(parse_text("float a[2][3];\n", options)->errors(), "");
  EXPECT_EQ(parse_text("float a[2][3];\n")->errors(), "");  // no language given: everything allowed
}

TEST(ParseDecl, GlobalInOutAndIntegerOperatorsNeedVersion130) {
  ParseOptions options;
  options.language = LanguageLevel{120, false, {}};
  auto parsed = parse_text("in vec4 v;\nvoid f(in int a, out int b) { b = a % 2; b <<= ~a; }\n", options);
  EXPECT_EQ(parsed->errors(),
            "test.glsl:1:1: error: 'in' and 'out' on global variables require #version 130 [E-VERSION]\n"
            "in vec4 v;\n"
            "^~\n"
            "test.glsl:2:37: error: the integer operators % << >> & | ^ ~ require #version 130 or GL_EXT_gpu_shader4 [E-VERSION]\n"
            "void f(in int a, out int b) { b = a % 2; b <<= ~a; }\n"
            "                                    ^\n"
            "test.glsl:2:44: error: the integer operators % << >> & | ^ ~ require #version 130 or GL_EXT_gpu_shader4 [E-VERSION]\n"
            "void f(in int a, out int b) { b = a % 2; b <<= ~a; }\n"
            "                                           ^~~\n"
            "test.glsl:2:48: error: the integer operators % << >> & | ^ ~ require #version 130 or GL_EXT_gpu_shader4 [E-VERSION]\n"
            "void f(in int a, out int b) { b = a % 2; b <<= ~a; }\n"
            "                                               ^\n");
  options.language = LanguageLevel{100, true, {}};
  EXPECT_NE(parse_text("out vec4 v;\n", options)->errors(), "");
  options.language = LanguageLevel{300, true, {}};
  EXPECT_EQ(parse_text("out vec4 v;\nvoid f() { int a = 5 % 2; }\n", options)->errors(), "");
  options.language = LanguageLevel{110, false, {"GL_EXT_gpu_shader4"}};
  EXPECT_EQ(parse_text("varying out vec4 v;\nvoid f() { int a = 5 % 2; }\n", options)->errors(), "");
  options.language = LanguageLevel{110, false, {"GL_ARB_explicit_attrib_location"}};
  EXPECT_EQ(parse_text("layout(location = 0) in vec4 v;\n", options)->errors(), "");
}

TEST(ParseDecl, LayoutIdentifiersOfLaterVersionsAreGated) {
  ParseOptions options;
  options.language = LanguageLevel{330, false, {}};
  auto parsed = parse_text("layout(binding = 1) uniform sampler2D s;\nlayout(std430) buffer B { float x[]; };\n"
                           "layout(location = 1 + 1) out vec4 c;\nlayout(location = 0, index = 1) out vec4 d;\n",
                           options);
  EXPECT_EQ(parsed->errors(),
            "test.glsl:1:8: error: layout(binding) requires #version 420 or GL_ARB_shading_language_420pack [E-VERSION]\n"
            "layout(binding = 1) uniform sampler2D s;\n"
            "       ^~~~~~~\n"
            "test.glsl:2:8: error: layout(std430) requires #version 430 or GL_ARB_shader_storage_buffer_object [E-VERSION]\n"
            "layout(std430) buffer B { float x[]; };\n"
            "       ^~~~~~\n"
            "test.glsl:3:19: error: constant expressions in layout qualifiers require #version 440 or "
            "GL_ARB_enhanced_layouts [E-VERSION]\n"
            "layout(location = 1 + 1) out vec4 c;\n"
            "                  ^~~~~\n");
  options.language->extensions = {"GL_ARB_shading_language_420pack", "GL_ARB_shader_storage_buffer_object",
                                  "GL_ARB_enhanced_layouts"};
  EXPECT_EQ(parse_text("layout(binding = 1) uniform sampler2D s;\nlayout(location = 1 + 1) out vec4 c;\n", options)
                ->errors(),
            "");
  options.language = LanguageLevel{310, true, {}};
  EXPECT_EQ(parse_text("layout(binding = 1) uniform sampler2D s;\n", options)->errors(), "");
}

TEST(ParseDecl, BlockLayoutsOnlyOnBlocks) {
  auto parsed = parse_text("layout(std140) vec4 a;\nstruct S { layout(row_major) mat4 m; };\n"
                           "uniform U { layout(shared) vec4 b; layout(row_major) mat4 c; };\n"
                           "layout(std140, row_major) uniform;\nlayout(std430) buffer B { vec4 d[]; };\n");
  EXPECT_EQ(parsed->errors(),
            "test.glsl:1:8: error: layout(std140) applies to uniform and buffer blocks, not to variables [E-LAYOUT]\n"
            "layout(std140) vec4 a;\n"
            "       ^~~~~~\n"
            "test.glsl:2:19: error: layout(row_major) applies to uniform and buffer blocks and their members, not to "
            "struct members [E-LAYOUT]\n"
            "struct S { layout(row_major) mat4 m; };\n"
            "                  ^~~~~~~~~\n"
            "test.glsl:3:20: error: layout(shared) applies to uniform and buffer blocks, not to members [E-LAYOUT]\n"
            "uniform U { layout(shared) vec4 b; layout(row_major) mat4 c; };\n"
            "                   ^~~~~~\n");
}

TEST(ParseDecl, SampleQualifiesOnlyInputsAndOutputs) {
  EXPECT_EQ(parse_text("sample in vec4 a;\nsample out vec4 b;\nin B { sample vec4 c; } blk;\n")->errors(), "");
  auto parsed = parse_text("sample uniform vec4 a;\nsample centroid in vec4 b;\nstruct S { sample vec4 c; };\n"
                           "uniform U { sample vec4 d; };\nvoid f() { sample vec4 e; }\n");
  EXPECT_EQ(parsed->errors(),
            "test.glsl:1:1: error: 'sample' applies only to 'in' and 'out' variables and blocks [E-QUALIFIER]\n"
            "sample uniform vec4 a;\n"
            "^~~~~~\n"
            "test.glsl:2:1: error: 'sample' and 'centroid' cannot qualify the same declaration [E-QUALIFIER]\n"
            "sample centroid in vec4 b;\n"
            "^~~~~~\n"
            "test.glsl:3:12: error: 'sample' applies only to 'in' and 'out' variables and blocks [E-QUALIFIER]\n"
            "struct S { sample vec4 c; };\n"
            "           ^~~~~~\n"
            "test.glsl:4:13: error: 'sample' applies only to 'in' and 'out' variables and blocks [E-QUALIFIER]\n"
            "uniform U { sample vec4 d; };\n"
            "            ^~~~~~\n"
            "test.glsl:5:12: error: 'sample' applies only to 'in' and 'out' variables and blocks [E-QUALIFIER]\n"
            "void f() { sample vec4 e; }\n"
            "           ^~~~~~\n");
}

// GL_EXT_spirv_intrinsics (issue 46): the qualifiers keep their canonical spelling, spirv_type is a type
// specifier of its own whose arguments may be type names; without a #version (everything allowed) the
// words need no #extension.
TEST(ParseDecl, SpirvIntrinsics) {
  EXPECT_EQ(dump_first("spirv_decorate(extensions = [\"SPV_X\"], 11, 4992) spirv_decorate(0) in vec2 v;"),
            "VariableDecl [spirv_decorate(extensions=[\"SPV_X\"], 11, 4992)] [spirv_decorate(0)] [in]\n"
            "  TypeSpecifier builtin vec2\n  Declarator v\n");
  EXPECT_EQ(dump_first("spirv_execution_mode(5027);"), "QualifierDecl [spirv_execution_mode(5027)]\n");
  EXPECT_EQ(dump_first("spirv_type(capabilities = [5347], id = 32, 5349, uint) p;"),
            "VariableDecl\n  TypeSpecifier spirv spirv_type(capabilities=[5347], id=32, 5349, uint)\n  Declarator p\n");
  auto parsed = parse_text("spirv_instruction(set = \"GLSL.std.450\", id = 35)\n"
                           "float modf(float x, spirv_by_reference float i, spirv_literal int m);\n"
                           "spirv_type(id = 32, 5349, uint) ptr;\n");
  EXPECT_EQ(parsed->errors(), "");
  const auto* fn = ast::dyn_cast<ast::FunctionDecl>(parsed->unit().decls.at(0));
  ASSERT_NE(fn, nullptr);
  ASSERT_EQ(fn->qualifiers.list.size(), 1u);
  EXPECT_EQ(fn->qualifiers.list[0].kind, ast::QualifierKind::Spirv);
  ASSERT_EQ(fn->qualifiers.list[0].spirv_args.size(), 2u);
  EXPECT_EQ(fn->qualifiers.list[0].spirv_args[0].kind, ast::SpirvArg::Kind::Set);
  EXPECT_TRUE(fn->params.at(1)->qualifiers.has("spirv_by_reference"));
  EXPECT_TRUE(fn->params.at(2)->qualifiers.has("spirv_literal"));
  const auto* ptr = ast::dyn_cast<ast::VariableDecl>(parsed->unit().decls.at(1));
  ASSERT_NE(ptr, nullptr);
  ASSERT_EQ(ptr->type->spirv_args.size(), 3u);
  EXPECT_EQ(ptr->type->spirv_args[2].kind, ast::SpirvArg::Kind::Type);
}

}  // namespace
}  // namespace safegi::testing
