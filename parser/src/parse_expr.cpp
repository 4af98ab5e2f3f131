// Expressions, by precedence climbing over GLSL's operator table.

#include <algorithm>
#include <cctype>
#include <initializer_list>
#include <vector>

#include "parser_impl.hpp"

namespace safegi::parser_detail {

using namespace ast;

namespace {

bool is_integer_operator(BinaryOp op) {
  switch (op) {
    case BinaryOp::Mod: case BinaryOp::Shl: case BinaryOp::Shr:
    case BinaryOp::BitAnd: case BinaryOp::BitXor: case BinaryOp::BitOr: return true;
    default: return false;
  }
}

bool is_integer_operator(AssignOp op) {
  switch (op) {
    case AssignOp::Mod: case AssignOp::Shl: case AssignOp::Shr:
    case AssignOp::And: case AssignOp::Xor: case AssignOp::Or: return true;
    default: return false;
  }
}

std::uint32_t height_of(std::initializer_list<const Expr*> children) {
  std::uint32_t h = 0;
  for (const Expr* c : children) {
    if (c != nullptr) h = std::max(h, c->height);
  }
  return h + 1;
}

bool literal_is_zero(std::string_view s, T kind) {
  if (kind == T::True || kind == T::False || kind == T::StringLit) return false;
  std::size_t i = 0;
  if (s.size() > 1 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) i = 2;
  bool hex = i == 2;
  for (; i < s.size(); ++i) {
    char c = s[i];
    if (c == '0' || c == '.') continue;
    if (!hex && (c == 'e' || c == 'E')) return true;  // 0.0e5 is zero whatever the exponent
    if ((c >= '1' && c <= '9') || (hex && ((c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F')))) return false;
    return true;  // a suffix: every digit before it was zero
  }
  return true;
}

}  // namespace

void Parser::check_height(Expr* e) {
  if (e->height > options_.max_expression_height) {
    if (!depth_reported_) {
      depth_reported_ = true;
      fail(code::E_LIMIT, e->range,
           "expression too deeply nested: more than " + std::to_string(options_.max_expression_height) +
               " levels of operators");
    }
    throw ParseError{};
  }
}

Expr* Parser::finish_expr(Expr* e, SourceLocation begin) {
  e->range = range_from(begin);
  return e;
}

LiteralExpr* Parser::make_literal(const PToken& token) {
  auto* lit = make<LiteralExpr>(token.range.begin);
  switch (token.kind) {
    case T::UintLit: lit->literal_kind = LiteralKind::Uint; break;
    case T::FloatLit: lit->literal_kind = LiteralKind::Float; break;
    case T::DoubleLit: lit->literal_kind = LiteralKind::Double; break;
    case T::StringLit: lit->literal_kind = LiteralKind::String; break;
    case T::True:
    case T::False: lit->literal_kind = LiteralKind::Bool; break;
    default: lit->literal_kind = LiteralKind::Int; break;
  }
  lit->spelling = std::string(token.text);
  lit->is_zero = literal_is_zero(token.text, token.kind);
  lit->range = token.range;
  return lit;
}

bool Parser::binary_op_here(BinaryOp& op, int& token_count) const {
  token_count = 1;
  switch (peek().kind) {
    case T::Star: op = BinaryOp::Mul; return true;
    case T::Slash: op = BinaryOp::Div; return true;
    case T::Percent: op = BinaryOp::Mod; return true;
    case T::Plus: op = BinaryOp::Add; return true;
    case T::Minus: op = BinaryOp::Sub; return true;
    case T::Shl: op = BinaryOp::Shl; return true;
    case T::Lt: op = BinaryOp::Lt; return true;
    case T::Gt:
      if (peek().glued) {
        if (peek(1).kind != T::Gt) return false;  // `>>=`, an assignment
        op = BinaryOp::Shr;
        token_count = 2;
        return true;
      }
      op = BinaryOp::Gt;
      return true;
    case T::Le: op = BinaryOp::Le; return true;
    case T::Ge: op = BinaryOp::Ge; return true;
    case T::EqEq: op = BinaryOp::Eq; return true;
    case T::Ne: op = BinaryOp::Ne; return true;
    case T::Amp: op = BinaryOp::BitAnd; return true;
    case T::Caret: op = BinaryOp::BitXor; return true;
    case T::Pipe: op = BinaryOp::BitOr; return true;
    case T::AmpAmp: op = BinaryOp::LogAnd; return true;
    case T::CaretCaret: op = BinaryOp::LogXor; return true;
    case T::PipePipe: op = BinaryOp::LogOr; return true;
    default: return false;
  }
}

bool Parser::prefix_op_here(UnaryOp& op) const {
  switch (peek().kind) {
    case T::Plus: op = UnaryOp::Plus; return true;
    case T::Minus: op = UnaryOp::Minus; return true;
    case T::Bang: op = UnaryOp::Not; return true;
    case T::Tilde: op = UnaryOp::BitNot; return true;
    case T::PlusPlus: op = UnaryOp::PreInc; return true;
    case T::MinusMinus: op = UnaryOp::PreDec; return true;
    default: return false;
  }
}

bool Parser::assign_op_here(AssignOp& op, int& token_count) const {
  token_count = 1;
  switch (peek().kind) {
    case T::Assign: op = AssignOp::Assign; return true;
    case T::StarAssign: op = AssignOp::Mul; return true;
    case T::SlashAssign: op = AssignOp::Div; return true;
    case T::PercentAssign: op = AssignOp::Mod; return true;
    case T::PlusAssign: op = AssignOp::Add; return true;
    case T::MinusAssign: op = AssignOp::Sub; return true;
    case T::ShlAssign: op = AssignOp::Shl; return true;
    case T::ShrAssign: op = AssignOp::Shr; return true;  // only if the lexer did not split it
    case T::AmpAssign: op = AssignOp::And; return true;
    case T::CaretAssign: op = AssignOp::Xor; return true;
    case T::PipeAssign: op = AssignOp::Or; return true;
    case T::Gt:
      if (peek().glued && peek(1).kind == T::Ge) {
        op = AssignOp::Shr;
        token_count = 2;
        return true;
      }
      return false;
    default: return false;
  }
}

Expr* Parser::parse_expression() {
  SourceLocation begin = here();
  Expr* lhs = parse_assignment();
  while (at(T::Comma)) {
    auto* comma = make<BinaryExpr>(begin);
    comma->op = BinaryOp::Comma;
    comma->op_range = advance().range;
    comma->lhs = lhs;
    comma->rhs = parse_assignment();
    comma->height = height_of({comma->lhs, comma->rhs});
    lhs = finish_expr(comma, begin);
    check_height(lhs);
  }
  return lhs;
}

// `a = b = c` is right-associative: the chain is read in a loop and built
// from the right, so it costs no stack. Each assignment after the first is one
// level of nesting (a lone `x = (((y)))` is as deep as its parentheses).
Expr* Parser::parse_assignment() {
  std::vector<AssignExpr*> chain;  // outermost first, each waiting for its right side
  NestingLevels levels(*this);
  Expr* rhs = nullptr;
  for (;;) {
    SourceLocation begin = here();
    Expr* lhs = parse_conditional();
    AssignOp op;
    int count;
    if (!assign_op_here(op, count)) {
      rhs = lhs;
      break;
    }
    if (!chain.empty()) levels.add();
    auto* assign = make<AssignExpr>(begin);
    assign->op = op;
    SourceLocation op_begin = here();
    for (int i = 0; i < count; ++i) advance();
    assign->op_range = range_from(op_begin);
    if (is_integer_operator(op)) require(LanguageFeature::integer_operators, assign->op_range);
    assign->lhs = lhs;
    chain.push_back(assign);
  }
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    AssignExpr* assign = *it;
    assign->rhs = rhs;
    assign->height = height_of({assign->lhs, assign->rhs});
    finish_expr(assign, assign->range.begin);
    check_height(assign);
    rhs = assign;
  }
  return rhs;
}

// A conditional inside an arm of another is one level; the outermost is not.
Expr* Parser::parse_conditional() {
  SourceLocation begin = here();
  Expr* condition = parse_binary(binary_op_precedence(BinaryOp::LogOr));
  if (!at(T::Question)) return condition;
  NestingLevels levels(*this);
  if (conditional_depth_ > 0) levels.add();
  struct Arms {
    unsigned& depth;
    explicit Arms(unsigned& d) : depth(++d) {}
    ~Arms() { --depth; }
  } arms(conditional_depth_);
  auto* ternary = make<TernaryExpr>(begin);
  advance();
  ternary->condition = condition;
  ternary->then_expr = parse_expression();
  expect(T::Colon, "':'", "in conditional expression");
  ternary->else_expr = parse_assignment();
  ternary->height = height_of({ternary->condition, ternary->then_expr, ternary->else_expr});
  finish_expr(ternary, begin);
  check_height(ternary);
  return ternary;
}

Expr* Parser::parse_binary(int min_precedence) {
  SourceLocation begin = here();
  Expr* lhs = parse_conversion();
  for (;;) {
    BinaryOp op;
    int count;
    if (!binary_op_here(op, count)) return lhs;
    int precedence = binary_op_precedence(op);
    if (precedence < min_precedence) return lhs;
    auto* binary = make<BinaryExpr>(begin);
    binary->op = op;
    SourceLocation op_begin = here();
    for (int i = 0; i < count; ++i) advance();
    binary->op_range = range_from(op_begin);
    if (is_integer_operator(op)) require(LanguageFeature::integer_operators, binary->op_range);
    binary->lhs = lhs;
    binary->rhs = parse_binary(precedence + 1);
    binary->height = height_of({binary->lhs, binary->rhs});
    lhs = finish_expr(binary, begin);
    check_height(lhs);
  }
}

bool Parser::at_in(std::size_t offset) const {
  const PToken& t = peek(offset);
  return t.kind == T::QualKw && t.text == "in";
}

// `in` never follows an expression in GLSL; `in T name` after a missing `;`
// is a declaration, not a conversion.
bool Parser::at_conversion() const {
  if (!at_in()) return false;
  if (peek(1).kind == T::LParen) return true;
  return at_annotation_name(1) && peek(2).kind != T::Ident;
}

Expr* Parser::parse_conversion() {
  SourceLocation begin = here();
  Expr* e = parse_unary();
  while (at_conversion()) {
    auto* convert = make<ConvertExpr>(begin);
    convert->operand = e;
    convert->in_range = advance().range;
    convert->target = parse_dim_primary();  // a name, or a parenthesised unit expression
    if (at(T::Caret))
      fail(code::E_SYNTAX, peek().range, "a power of a unit after 'in' needs parentheses, e.g. x in (meter^2)");
    convert->height = height_of({e});
    e = finish_expr(convert, begin);
    check_height(e);
  }
  return e;
}

// Prefix operators are read in a loop and applied from the inside out: no
// stack per operator. Each operator after the first is one level of nesting.
Expr* Parser::parse_unary() {
  struct Prefix {
    UnaryOp op;
    SourceRange range;
  };
  std::vector<Prefix> prefixes;
  NestingLevels levels(*this);
  for (UnaryOp op; prefix_op_here(op);) {
    if (!prefixes.empty()) levels.add();
    prefixes.push_back({op, advance().range});
    if (op == UnaryOp::BitNot) require(LanguageFeature::integer_operators, prefixes.back().range);
  }
  Expr* e = parse_postfix();
  for (auto it = prefixes.rbegin(); it != prefixes.rend(); ++it) {
    auto* unary = make<UnaryExpr>(it->range.begin);
    unary->op = it->op;
    unary->op_range = it->range;
    unary->operand = e;
    unary->height = height_of({e});
    e = finish_expr(unary, it->range.begin);
    check_height(e);
  }
  return e;
}

Expr* Parser::parse_postfix() {
  SourceLocation begin = here();
  Expr* e = parse_primary();
  for (;;) {
    if (at(T::LBracket)) {
      auto* index = make<IndexExpr>(begin);
      advance();
      index->base = e;
      {
        DepthGuard guard(*this);  // the brackets are one level
        index->index = parse_expression();
      }
      expect(T::RBracket, "']'", "after index");
      index->height = height_of({index->base, index->index});
      e = finish_expr(index, begin);
    } else if (at(T::Dot)) {
      advance();
      const PToken& name = peek();
      if (name.text.empty() || !(std::isalpha(static_cast<unsigned char>(name.text[0])) || name.text[0] == '_')) {
        fail_expected("a field name or swizzle", "after '.'");
      }
      advance();
      if (at(T::LParen)) {
        auto* method = make<MethodCallExpr>(begin);
        method->base = e;
        method->method = std::string(name.text);
        method->method_range = name.range;
        method->args = parse_method_args();
        std::uint32_t h = e->height;
        for (Expr* a : method->args) h = std::max(h, a->height);
        method->height = h + 1;
        e = finish_expr(method, begin);
      } else {
        auto* member = make<MemberExpr>(begin);
        member->base = e;
        member->member = std::string(name.text);
        member->member_range = name.range;
        member->height = height_of({e});
        e = finish_expr(member, begin);
      }
    } else if (at(T::LParen) && isa<IndexExpr>(e)) {  // subroutine array element: f[i](x)
      auto* call = make<CallExpr>(begin);
      call->callee_expr = e;
      parse_call_args(call);
      call->height = std::max(call->height, e->height + 1);
      e = call;
    } else if (at(T::PlusPlus) || at(T::MinusMinus)) {
      auto* unary = make<UnaryExpr>(begin);
      unary->op = at(T::PlusPlus) ? UnaryOp::PostInc : UnaryOp::PostDec;
      unary->op_range = advance().range;
      unary->operand = e;
      unary->height = height_of({e});
      e = finish_expr(unary, begin);
    } else {
      return e;
    }
    check_height(e);
  }
}

std::vector<Expr*> Parser::parse_method_args() {
  DepthGuard guard(*this);  // the argument list's parentheses are one level
  std::vector<Expr*> args;
  expect(T::LParen, "'('", "");
  if (!at(T::RParen)) {
    do {
      args.push_back(parse_assignment());
    } while (accept(T::Comma));
  }
  expect(T::RParen, "')'", "to close argument list");
  return args;
}

Expr* Parser::parse_call_args(CallExpr* call) {
  DepthGuard guard(*this);  // the argument list's parentheses are one level
  SourceLocation begin = call->range.begin;
  expect(T::LParen, "'('", "");
  if (at(T::TypeKw) && peek().text == "void" && peek(1).kind == T::RParen) {
    advance();
    call->void_arg = true;
  } else if (!at(T::RParen)) {
    do {
      call->args.push_back(parse_assignment());
    } while (accept(T::Comma));
  }
  expect(T::RParen, "')'", "to close argument list");
  std::uint32_t h = 0;
  for (Expr* a : call->args) h = std::max(h, a->height);
  call->height = h + 1;
  finish_expr(call, begin);
  check_height(call);
  return call;
}

Expr* Parser::parse_primary() {
  SourceLocation begin = here();
  const PToken& t = peek();
  switch (t.kind) {
    case T::IntLit:
    case T::UintLit:
    case T::FloatLit:
    case T::DoubleLit:
    case T::StringLit:
    case T::True:
    case T::False:
      return make_literal(advance());
    case T::LParen: {
      DepthGuard guard(*this);
      auto* paren = make<ParenExpr>(begin);
      advance();
      paren->inner = parse_expression();
      expect(T::RParen, "')'", "to close parenthesised expression");
      paren->height = height_of({paren->inner});
      return finish_expr(paren, begin);
    }
    case T::QualKw:
      // GL_EXT_nonuniform_qualifier: `nonuniformEXT(i)` is a qualifier used as a function.
      if (t.text == "nonuniformEXT" && peek(1).kind == T::LParen) {
        auto* call = make<CallExpr>(begin);
        call->callee = std::string(t.text);
        call->callee_range = advance().range;
        return parse_call_args(call);
      }
      fail_expected("an expression", "");
    case T::TypeKw: {
      auto* call = make<CallExpr>(begin);
      call->constructor_type = parse_type_specifier();
      if (!at(T::LParen)) fail_expected("'(' to construct a value", "after type '" + call->constructor_type->name + "'");
      return parse_call_args(call);
    }
    case T::Ident: {
      bool annotated = is_annotated_type_word(t) && peek(1).kind == T::Lt && scan_annotation(pos_ + 1, 0) != 0;
      if (annotated || is_type_name(t.text)) {
        std::size_t end = scan_type_specifier(pos_);
        if (end != 0 && tokens_[end].kind == T::LParen) {
          auto* call = make<CallExpr>(begin);
          call->constructor_type = parse_type_specifier();
          return parse_call_args(call);
        }
      }
      if (peek(1).kind == T::LParen) {
        auto* call = make<CallExpr>(begin);
        call->callee = std::string(t.text);
        call->callee_range = advance().range;
        return parse_call_args(call);
      }
      auto* id = make<IdentifierExpr>(begin);
      id->name = std::string(advance().text);
      return finish_expr(id, begin);
    }
    default:
      fail_expected("an expression", "");
  }
}

}  // namespace safegi::parser_detail
