// Statements, and error recovery by synchronising at ';' and '}'.

#include "parser_impl.hpp"

namespace safegi::parser_detail {

using namespace ast;

void Parser::synchronize_statement() {
  // Skip to the end of the broken statement: past a ';' at this nesting level,
  // or up to (not past) a '}' that closes the enclosing block.
  int depth = 0;
  while (!at(T::Eof)) {
    T k = peek().kind;
    if (k == T::LBrace || k == T::LParen || k == T::LBracket) {
      ++depth;
    } else if (k == T::RParen || k == T::RBracket) {
      if (depth > 0) --depth;
    } else if (k == T::RBrace) {
      if (depth == 0) return;
      if (--depth == 0) {
        advance();
        accept(T::Semicolon);
        return;
      }
    } else if (k == T::Semicolon && depth == 0) {
      advance();
      return;
    }
    advance();
  }
}

void Parser::synchronize_global() {
  // Like synchronize_statement, but a stray '}' at global scope is skipped too.
  if (at(T::RBrace)) {
    advance();
    return;
  }
  synchronize_statement();
  while (scopes_.size() > 2) pop_scope();  // built-ins + the global scope
}

Stmt* Parser::parse_statement_or_recover() {
  std::size_t start = pos_;
  try {
    return parse_statement();
  } catch (const ParseError&) {
    synchronize_statement();
    if (pos_ == start && !at(T::RBrace)) advance();
    return nullptr;
  }
}

CompoundStmt* Parser::parse_compound(bool new_scope) {
  DepthGuard guard(*this);
  SourceLocation begin = here();
  auto* block = make<CompoundStmt>(begin);
  expect(T::LBrace, "'{'", "");
  if (new_scope) push_scope();
  std::size_t scope_depth = scopes_.size();
  while (!at(T::RBrace) && !at(T::Eof) && !diagnostics_.limit_reached()) {
    if (Stmt* s = parse_statement_or_recover()) block->statements.push_back(s);
    while (scopes_.size() > scope_depth) pop_scope();  // a statement that threw leaves no scopes behind
  }
  if (new_scope) pop_scope();
  if (!at(T::RBrace)) {
    fail(
        code::E_SYNTAX, peek().range,
        "expected '}' to close the block opened at line " + std::to_string(begin.line) + ", found " + describe(peek()));
  }
  advance();
  block->range = range_from(begin);
  return block;
}

// The body of if, else, while, do and for. A block is one level of nesting
// (parse_compound); so is a body without braces (`if (a) if (b) ...`).
Stmt* Parser::parse_substatement() {
  if (at(T::LBrace)) return parse_statement();
  DepthGuard guard(*this);
  return parse_statement();
}

Stmt* Parser::parse_statement() {
  SourceLocation begin = here();
  switch (peek().kind) {
    case T::LBrace:
      return parse_compound(true);
    case T::If:
      return parse_if();
    case T::Switch:
      return parse_switch();
    case T::While:
      return parse_while();
    case T::Do:
      return parse_do();
    case T::For:
      return parse_for();
    case T::Break:
    case T::Continue:
    case T::Discard:
    case T::Return:
      return parse_jump();
    case T::Case: {
      auto* label = make<CaseLabel>(begin);
      advance();
      label->value = parse_expression();
      expect(T::Colon, "':'", "after case value");
      label->range = range_from(begin);
      return label;
    }
    case T::Default: {
      auto* label = make<DefaultLabel>(begin);
      advance();
      expect(T::Colon, "':'", "after 'default'");
      label->range = range_from(begin);
      return label;
    }
    case T::LBracket:
      if (peek(1).kind == T::LBracket) return parse_attributed_statement();
      break;
    case T::Semicolon: {
      auto* empty = make<EmptyStmt>(begin);
      advance();
      empty->range = range_from(begin);
      return empty;
    }
    default:
      break;
  }
  if (at(T::Ident) && peek().text == "demote" && peek(1).kind == T::Semicolon && lookup("demote") == nullptr) {
    auto* demote = make<JumpStmt>(begin);
    demote->kind = NodeKind::DemoteStmt;
    advance();
    advance();
    demote->range = range_from(begin);
    return demote;
  }
  return parse_simple_statement();
}

Stmt* Parser::parse_attributed_statement() {
  SourceLocation begin = here();
  std::vector<StatementAttribute> attributes;
  advance();
  advance();
  do {
    const PToken& name = expect(T::Ident, "an attribute name", "in '[[ ]]'");
    StatementAttribute attribute;
    attribute.name = std::string(name.text);
    attribute.name_range = name.range;
    if (accept(T::LParen)) {
      attribute.argument = parse_assignment();
      expect(T::RParen, "')'", "after the attribute's argument");
    }
    attributes.push_back(std::move(attribute));
  } while (accept(T::Comma));
  expect(T::RBracket, "']]'", "to close the attributes");
  expect(T::RBracket, "']]'", "to close the attributes");
  const SourceRange attributes_range = range_from(begin);
  require(LanguageFeature::control_flow_attributes, attributes_range);
  // GL_EXT_control_flow_attributes: only selection, switch and iteration statements take them.
  const T k = peek().kind;
  if (k != T::If && k != T::Switch && k != T::While && k != T::Do && k != T::For) {
    fail_expected("'if', 'switch', 'for', 'while' or 'do'", "after '[[ ]]' attributes");
  }
  Stmt* stmt = parse_statement();
  stmt->attributes = std::move(attributes);
  stmt->attributes_range = attributes_range;
  return stmt;
}

Stmt* Parser::parse_simple_statement() {
  SourceLocation begin = here();
  if (at_declaration() || at(T::Template)) {
    auto* stmt = make<DeclStmt>(begin);
    stmt->decl = parse_declaration(false);
    stmt->range = range_from(begin);
    return stmt;
  }
  auto* stmt = make<ExprStmt>(begin);
  stmt->expr = parse_expression();
  expect_semicolon("after expression");
  stmt->range = range_from(begin);
  return stmt;
}

Stmt* Parser::parse_if() {
  SourceLocation begin = here();
  auto* stmt = make<IfStmt>(begin);
  advance();
  expect(T::LParen, "'('", "after 'if'");
  stmt->condition = parse_expression();
  expect(T::RParen, "')'", "after if condition");
  push_scope();
  stmt->then_stmt = parse_substatement();
  pop_scope();
  if (accept(T::Else)) {
    push_scope();
    stmt->else_stmt = parse_substatement();
    pop_scope();
  }
  stmt->range = range_from(begin);
  return stmt;
}

Stmt* Parser::parse_switch() {
  SourceLocation begin = here();
  auto* stmt = make<SwitchStmt>(begin);
  advance();
  expect(T::LParen, "'('", "after 'switch'");
  stmt->selector = parse_expression();
  expect(T::RParen, "')'", "after switch selector");
  if (!at(T::LBrace)) fail_expected("'{'", "after switch selector");
  stmt->body = parse_compound(true);
  stmt->range = range_from(begin);
  return stmt;
}

Condition Parser::parse_condition() {
  Condition condition;
  if (!at_declaration()) {
    condition.expr = parse_expression();
    return condition;
  }
  SourceLocation begin = here();
  auto* decl = make<VariableDecl>(begin);
  decl->qualifiers = parse_qualifiers();
  decl->type = parse_type_specifier();
  Declarator d;
  const PToken& name = expect(T::Ident, "a variable name", "in condition");
  d.name = std::string(name.text);
  d.name_range = name.range;
  expect(T::Assign, "'='", "after the variable declared in a condition");
  d.initializer = parse_assignment();
  d.range = range_from(name.range.begin);
  declare(d.name, NameKind::Value);
  decl->declarators.push_back(std::move(d));
  decl->range = range_from(begin);
  condition.decl = decl;
  return condition;
}

Stmt* Parser::parse_while() {
  SourceLocation begin = here();
  auto* stmt = make<WhileStmt>(begin);
  advance();
  push_scope();
  expect(T::LParen, "'('", "after 'while'");
  stmt->condition = parse_condition();
  expect(T::RParen, "')'", "after loop condition");
  stmt->body = parse_substatement();
  pop_scope();
  stmt->range = range_from(begin);
  return stmt;
}

Stmt* Parser::parse_do() {
  SourceLocation begin = here();
  auto* stmt = make<DoStmt>(begin);
  advance();
  push_scope();
  stmt->body = parse_substatement();
  pop_scope();
  expect(T::While, "'while'", "after do-loop body");
  expect(T::LParen, "'('", "after 'while'");
  stmt->condition = parse_expression();
  expect(T::RParen, "')'", "after loop condition");
  expect_semicolon("after do-while loop");
  stmt->range = range_from(begin);
  return stmt;
}

Stmt* Parser::parse_for() {
  SourceLocation begin = here();
  auto* stmt = make<ForStmt>(begin);
  advance();
  push_scope();
  expect(T::LParen, "'('", "after 'for'");
  if (at(T::Semicolon)) {
    auto* empty = make<EmptyStmt>(here());
    advance();
    empty->range = range_from(empty->range.begin);
    stmt->init = empty;
  } else {
    stmt->init = parse_simple_statement();
  }
  if (!at(T::Semicolon)) stmt->condition = parse_condition();
  expect_semicolon("after for-loop condition");
  if (!at(T::RParen)) stmt->increment = parse_expression();
  expect(T::RParen, "')'", "to close for-loop header");
  stmt->body = parse_substatement();
  pop_scope();
  stmt->range = range_from(begin);
  return stmt;
}

Stmt* Parser::parse_jump() {
  SourceLocation begin = here();
  T kind = advance().kind;
  if (kind == T::Return) {
    auto* stmt = make<ReturnStmt>(begin);
    if (!at(T::Semicolon)) stmt->value = parse_expression();
    expect_semicolon("after return statement");
    stmt->range = range_from(begin);
    return stmt;
  }
  auto* stmt = make<JumpStmt>(begin);
  stmt->kind = kind == T::Break ? NodeKind::BreakStmt
               : kind == T::Continue ? NodeKind::ContinueStmt
                                     : NodeKind::DiscardStmt;
  expect_semicolon(kind == T::Break      ? "after 'break'"
                   : kind == T::Continue ? "after 'continue'"
                                         : "after 'discard'");
  stmt->range = range_from(begin);
  return stmt;
}

}  // namespace safegi::parser_detail
