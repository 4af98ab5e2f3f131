// Statements: blocks, selection, loops with declarations in conditions,
// switch, jumps, and the declaration-or-expression decision.

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace safegi::testing {
namespace {

TEST(ParseStmt, IfElseChainsAndDanglingElse) {
  EXPECT_EQ(dump_first("void f() { if (a) if (b) x(); else y(); }"),
            "IfStmt\n  condition: IdentifierExpr a\n  then: IfStmt\n    condition: IdentifierExpr b\n"
            "    then: ExprStmt\n      CallExpr x\n    else: ExprStmt\n      CallExpr y\n");
}

TEST(ParseStmt, ForWithDeclarationAndEmptyParts) {
  EXPECT_EQ(dump_first("void f() { for (int i = 0; i < 4; ++i) continue; }"),
            "ForStmt\n  init: DeclStmt\n    VariableDecl\n      TypeSpecifier builtin int\n"
            "      Declarator i\n        init: LiteralExpr 0\n"
            "  condition: BinaryExpr <\n    IdentifierExpr i\n    LiteralExpr 4\n"
            "  increment: UnaryExpr ++\n    IdentifierExpr i\n  body: ContinueStmt\n");
  EXPECT_EQ(dump_first("void f() { for (;;) break; }"), "ForStmt\n  init: EmptyStmt\n  body: BreakStmt\n");
}

TEST(ParseStmt, AttributesBeforeLoopsIfsAndSwitches) {
  EXPECT_EQ(dump_first("void f() { [[unroll, dependency_length(4)]] for (;;) break; }"),
            "ForStmt [[unroll, dependency_length]]\n  dependency_length: LiteralExpr 4\n  init: EmptyStmt\n  body: BreakStmt\n");
  EXPECT_EQ(dump_first("void f() { [[flatten]] if (a) x(); }"),
            "IfStmt [[flatten]]\n  condition: IdentifierExpr a\n  then: ExprStmt\n    CallExpr x\n");
  auto parsed = parse_text("void f() { [[unroll]] x(); }");
  EXPECT_EQ(parsed->errors(), "test.glsl:1:23: error: expected 'if', 'switch', 'for', 'while' or 'do' after '[[ ]]' attributes, found 'x' [E-SYNTAX]\n"
                              "void f() { [[unroll]] x(); }\n"
                              "                      ^\n");
}

TEST(ParseStmt, DeclarationsInConditions) {
  EXPECT_EQ(dump_first("void f() { while (bool go = k > 0) k--; }"),
            "WhileStmt\n  condition: VariableDecl\n    TypeSpecifier builtin bool\n    Declarator go\n"
            "      init: BinaryExpr >\n        IdentifierExpr k\n        LiteralExpr 0\n"
            "  body: ExprStmt\n    UnaryExpr -- postfix\n      IdentifierExpr k\n");
  EXPECT_EQ(dump_first("void f() { for (; bool b = g(); ) {} }").substr(0, 64),
            "ForStmt\n  init: EmptyStmt\n  condition: VariableDecl\n    TypeSpec");
}

TEST(ParseStmt, DoWhileSwitchAndJumps) {
  EXPECT_EQ(dump_first("void f() { do { discard; } while (x); }"),
            "DoStmt\n  body: CompoundStmt\n    DiscardStmt\n  condition: IdentifierExpr x\n");
  EXPECT_EQ(dump_first("void f() { switch (i) { case 0: case 1 + 1: return; default: break; } }"),
            "SwitchStmt\n  IdentifierExpr i\n  CompoundStmt\n    CaseLabel\n      LiteralExpr 0\n"
            "    CaseLabel\n      BinaryExpr +\n        LiteralExpr 1\n        LiteralExpr 1\n"
            "    ReturnStmt\n    DefaultLabel\n    BreakStmt\n");
  EXPECT_EQ(dump_first("void f() { demote; }"), "DemoteStmt\n");
}

TEST(ParseStmt, DeclarationOrExpression) {
  // `a * b;` is an expression; `T x;` a declaration; `T[2] y;` one too once T is a type.
  auto parsed = parse_text("struct T { int i; }; void f() { a * b; T x; T[2] y; a[2] = 1; vec3(1.0); }");
  ASSERT_FALSE(parsed->diagnostics.has_errors()) << parsed->errors();
  const auto* fn = ast::dyn_cast<ast::FunctionDecl>(parsed->unit().decls[1]);
  ASSERT_EQ(fn->body->statements.size(), 5u);
  EXPECT_TRUE(ast::isa<ast::ExprStmt>(fn->body->statements[0]));
  EXPECT_TRUE(ast::isa<ast::DeclStmt>(fn->body->statements[1]));
  EXPECT_TRUE(ast::isa<ast::DeclStmt>(fn->body->statements[2]));
  EXPECT_TRUE(ast::isa<ast::ExprStmt>(fn->body->statements[3]));
  EXPECT_TRUE(ast::isa<ast::ExprStmt>(fn->body->statements[4]));
}

TEST(ParseStmt, LocalVariableShadowsStructName) {
  auto parsed = parse_text("struct S { int i; }; void f() { float S = 1.0; S * 2.0; }");
  ASSERT_FALSE(parsed->diagnostics.has_errors()) << parsed->errors();
  const auto* fn = ast::dyn_cast<ast::FunctionDecl>(parsed->unit().decls[1]);
  EXPECT_TRUE(ast::isa<ast::ExprStmt>(fn->body->statements[1]));
}

TEST(ParseStmt, LocalPrototypeAndNestedBlocks) {
  auto parsed = parse_text("void f() { float g(float); { { ; } } }");
  ASSERT_FALSE(parsed->diagnostics.has_errors()) << parsed->errors();
}

}  // namespace
}  // namespace safegi::testing
