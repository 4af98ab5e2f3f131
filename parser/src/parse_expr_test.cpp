// Expressions: every operator with GLSL's precedence and associativity,
// postfix forms, constructors and calls.

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace safegi::testing {
namespace {

// Fully parenthesised print of an expression, to read precedence at a glance.
std::string shape(std::string_view source) {
  auto parsed = parse_text("void f() { t = " + std::string(source) + "; }");
  EXPECT_FALSE(parsed->diagnostics.has_errors()) << parsed->errors();
  if (parsed->diagnostics.has_errors()) return "";
  const auto* fn = ast::dyn_cast<ast::FunctionDecl>(parsed->unit().decls.front());
  const auto* stmt = ast::dyn_cast<ast::ExprStmt>(fn->body->statements.front());
  struct Shaper {
    std::string operator()(const ast::Expr* e) const {
      using namespace ast;
      if (const auto* b = dyn_cast<BinaryExpr>(e)) {
        return "(" + (*this)(b->lhs) + " " + std::string(binary_op_spelling(b->op)) + " " + (*this)(b->rhs) + ")";
      }
      if (const auto* a = dyn_cast<AssignExpr>(e)) {
        return "(" + (*this)(a->lhs) + " " + std::string(assign_op_spelling(a->op)) + " " + (*this)(a->rhs) + ")";
      }
      if (const auto* u = dyn_cast<UnaryExpr>(e)) {
        bool post = u->op == UnaryOp::PostInc || u->op == UnaryOp::PostDec;
        return post ? "(" + (*this)(u->operand) + std::string(unary_op_spelling(u->op)) + ")"
                    : "(" + std::string(unary_op_spelling(u->op)) + (*this)(u->operand) + ")";
      }
      if (const auto* t = dyn_cast<TernaryExpr>(e)) {
        return "(" + (*this)(t->condition) + " ? " + (*this)(t->then_expr) + " : " + (*this)(t->else_expr) + ")";
      }
      if (const auto* p = dyn_cast<ParenExpr>(e)) return (*this)(p->inner);
      return print_expression(*e);
    }
  };
  return Shaper{}(ast::dyn_cast<ast::AssignExpr>(stmt->expr)->rhs);
}

TEST(ParseExpr, MultiplicativeBindsTighterThanAdditive) {
  EXPECT_EQ(shape("a + b * c - d / e % f"), "((a + (b * c)) - ((d / e) % f))");
}

TEST(ParseExpr, FullPrecedenceLadder) {
  EXPECT_EQ(shape("a || b ^^ c && d | e ^ f & g == h < i << j + k * l"),
            "(a || (b ^^ (c && (d | (e ^ (f & (g == (h < (i << (j + (k * l)))))))))))");
}

TEST(ParseExpr, LeftAssociative) {
  EXPECT_EQ(shape("a - b - c"), "((a - b) - c)");
  EXPECT_EQ(shape("a / b / c"), "((a / b) / c)");
  EXPECT_EQ(shape("a < b > c"), "((a < b) > c)");
}

TEST(ParseExpr, RelationalAndShift) {
  EXPECT_EQ(shape("a >> 2 >= b << 1"), "((a >> 2) >= (b << 1))");
  EXPECT_EQ(shape("a > b >> c"), "(a > (b >> c))");
  EXPECT_EQ(shape("a <= b != c >= d"), "((a <= b) != (c >= d))");
}

TEST(ParseExpr, AssignmentIsRightAssociative) {
  EXPECT_EQ(shape("a = b += c >>= d <<= e"), "(a = (b += (c >>= (d <<= e))))");
  EXPECT_EQ(shape("a *= b /= c %= d &= e ^= f |= g -= h"),
            "(a *= (b /= (c %= (d &= (e ^= (f |= (g -= h)))))))");
}

TEST(ParseExpr, TernaryNestsToTheRight) {
  EXPECT_EQ(shape("a ? b : c ? d : e"), "(a ? b : (c ? d : e))");
  EXPECT_EQ(shape("a || b ? c = d : e"), "((a || b) ? (c = d) : e)");
}

TEST(ParseExpr, CommaInParentheses) { EXPECT_EQ(shape("(a, b = c, d)"), "((a , (b = c)) , d)"); }

TEST(ParseExpr, UnaryAndPostfix) {
  EXPECT_EQ(shape("-a * !b + ~c"), "(((-a) * (!b)) + (~c))");
  EXPECT_EQ(shape("++a + b--"), "((++a) + (b--))");
  EXPECT_EQ(shape("- -a"), "(-(-a))");
  EXPECT_EQ(shape("-a.x[1]++"), "(-(a.x[1]++))");
}

TEST(ParseExpr, SwizzleIndexAndLength) {
  EXPECT_EQ(dump_expr("v.xyz[i].y"),
            "MemberExpr .y\n  IndexExpr\n    MemberExpr .xyz\n      IdentifierExpr v\n    IdentifierExpr i\n");
  EXPECT_EQ(dump_expr("a[2].length()"), "MethodCallExpr .length()\n  IndexExpr\n    IdentifierExpr a\n    LiteralExpr 2\n");
}

TEST(ParseExpr, ConstructorsAndCalls) {
  EXPECT_EQ(dump_expr("vec3(1.0)"), "CallExpr\n  constructor: TypeSpecifier builtin vec3\n  LiteralExpr 1.0\n");
  EXPECT_EQ(dump_expr("f(void)"), "CallExpr f (void)\n");
  EXPECT_EQ(dump_expr("max(a, b)"), "CallExpr max\n  IdentifierExpr a\n  IdentifierExpr b\n");
  EXPECT_EQ(dump_expr("float[2](1.0, 2.0)"),
            "CallExpr\n  constructor: TypeSpecifier builtin float\n    ArrayDim\n      LiteralExpr 2\n"
            "  LiteralExpr 1.0\n  LiteralExpr 2.0\n");
  EXPECT_EQ(dump_expr("float[](1.0)"),
            "CallExpr\n  constructor: TypeSpecifier builtin float\n    ArrayDim unsized\n  LiteralExpr 1.0\n");
}

TEST(ParseExpr, StructConstructorNeedsKnownStruct) {
  auto parsed = parse_text("struct S { float x; }; void f() { S s = S(1.0); g(1.0); }");
  ASSERT_FALSE(parsed->diagnostics.has_errors()) << parsed->errors();
  std::string dump = parsed->dump();
  EXPECT_NE(dump.find("constructor: TypeSpecifier named S"), std::string::npos) << dump;
  EXPECT_NE(dump.find("CallExpr g"), std::string::npos) << dump;
}

TEST(ParseExpr, Literals) {
  auto parsed = parse_text("void f() { t = 0x1Fu + 017 + 1.5e3 + 2.0lf + .5 + 3.f + true; z = 0.0; w = 0x0; }");
  ASSERT_FALSE(parsed->diagnostics.has_errors()) << parsed->errors();
  std::string dump = parsed->dump();
  for (const char* lit : {"0x1Fu", "017", "1.5e3", "2.0lf", ".5", "3.f", "true"}) {
    EXPECT_NE(dump.find(std::string("LiteralExpr ") + lit + "\n"), std::string::npos) << lit;
  }
  const auto* fn = ast::dyn_cast<ast::FunctionDecl>(parsed->unit().decls.front());
  const auto* zero = ast::dyn_cast<ast::LiteralExpr>(
      ast::dyn_cast<ast::AssignExpr>(ast::dyn_cast<ast::ExprStmt>(fn->body->statements[1])->expr)->rhs);
  ASSERT_NE(zero, nullptr);
  EXPECT_TRUE(zero->is_zero);
  EXPECT_EQ(zero->literal_kind, ast::LiteralKind::Float);
}

TEST(ParseExpr, InitializerLists) {
  EXPECT_EQ(dump_first("void f() { float a[2] = {1.0, 2.0,}; }"),
            "DeclStmt\n  VariableDecl\n    TypeSpecifier builtin float\n    Declarator a\n      ArrayDim\n"
            "        LiteralExpr 2\n      init: InitializerList\n        LiteralExpr 1.0\n        LiteralExpr 2.0\n");
}

TEST(ParseExpr, RangesCoverTheExpression) {
  auto parsed = parse_text("void f() { t = (a + b) * c; }");
  const auto* fn = ast::dyn_cast<ast::FunctionDecl>(parsed->unit().decls.front());
  const auto* assign = ast::dyn_cast<ast::AssignExpr>(ast::dyn_cast<ast::ExprStmt>(fn->body->statements[0])->expr);
  EXPECT_EQ(assign->rhs->range.begin.column, 16u);
  EXPECT_EQ(assign->rhs->range.end.column, 27u);
  const auto* mul = ast::dyn_cast<ast::BinaryExpr>(assign->rhs);
  EXPECT_EQ(mul->op_range.begin.column, 24u);
}

}  // namespace
}  // namespace safegi::testing
