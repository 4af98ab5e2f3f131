// The SafeGI annotation syntax: template headers, `dimension`/`unit`/`space`
// declarations, annotations `<…>` on types and dimension expressions.

#include <charconv>

#include "parser_impl.hpp"

namespace safegi::parser_detail {

using namespace ast;

// ------------------------------------------------------------ annotations

void Parser::parse_template_header(std::vector<TemplateParam>& params, SourceRange& range) {
  SourceLocation begin = here();
  advance();  // template
  expect(T::Lt, "'<'", "after 'template'");
  do {
    TemplateParam param;
    SourceLocation param_begin = here();
    if (at(T::Ident) && peek().text == "dimension") {
      param.kind = TemplateParamKind::Dimension;
    } else if (at(T::Ident) && peek().text == "space") {
      param.kind = TemplateParamKind::Space;
    } else {
      fail_expected("'dimension' or 'space'", "in template parameter list");
    }
    advance();
    const PToken& name = expect(T::Ident, "a parameter name", "in template parameter list");
    param.name = std::string(name.text);
    param.name_range = name.range;
    param.range = range_from(param_begin);
    params.push_back(std::move(param));
  } while (accept(T::Comma));
  expect(T::Gt, "'>'", "to close template parameter list");
  range = range_from(begin);
}

Decl* Parser::parse_annotation_declaration() {
  SourceLocation begin = here();
  std::string_view word = advance().text;
  const PToken& name = advance();  // checked to be an identifier by at_annotation_declaration
  Decl* result = nullptr;
  if (word == "dimension") {
    auto* decl = make<DimensionDecl>(begin);
    decl->name = std::string(name.text);
    decl->name_range = name.range;
    if (accept(T::Colon)) {
      // `dimension angle : ratio;`: the only kind a base may be given.
      if (!(at(T::Ident) && peek().text == "ratio")) fail_expected("'ratio'", "after ':' in a dimension declaration");
      advance();
      decl->ratio = true;
    } else if (accept(T::Assign)) {
      decl->definition = parse_dim_expr();
    }
    expect_semicolon("after dimension declaration");
    result = decl;
  } else if (word == "unit") {
    auto* decl = make<UnitDecl>(begin);
    decl->name = std::string(name.text);
    decl->name_range = name.range;
    expect(T::Colon, "':' and the unit's dimension", "after unit name");
    decl->dimension = parse_dim_expr();
    expect(T::Assign, "'=' and the unit's scale", "after unit dimension");
    decl->scale = parse_conditional();
    expect_semicolon("after unit declaration");
    result = decl;
  } else {
    auto* decl = make<SpaceDecl>(begin);
    decl->name = std::string(name.text);
    decl->name_range = name.range;
    if (accept(T::Colon)) {
      // `space view : eye;` or `space shading : frame;`: the one property a space may be given.
      if (!(at(T::Ident) && (peek().text == "eye" || peek().text == "frame")))
        fail_expected("'eye' or 'frame'", "after ':' in a space declaration");
      (peek().text == "frame" ? decl->frame : decl->eye) = true;
      advance();
    }
    expect_semicolon("after space declaration");
    result = decl;
  }
  result->range = range_from(begin);
  return result;
}

Annotation* Parser::parse_annotation() {
  DepthGuard guard(*this);
  auto* annotation = make<Annotation>(here());
  expect(T::Lt, "'<'", "");
  do {
    annotation->args.push_back(parse_annotation_arg());
  } while (accept(T::Comma));
  if (!at(T::Gt)) fail_expected("',' or '>'", "in annotation");
  advance();
  annotation->range.end = prev_end_;
  return annotation;
}

Node* Parser::parse_annotation_arg() {
  if (at(T::TypeKw) || (is_annotated_type_word(peek()) && peek(1).kind == T::Lt)) {
    return parse_type_specifier_nonarray();
  }
  SourceLocation begin = here();
  DimExpr* dimension = parse_dim_expr();
  if (!at_in()) return dimension;
  auto* measured = make<DimUnit>(begin);  // `length in centimeter`
  measured->dimension = dimension;
  measured->in_range = advance().range;
  measured->unit = parse_dim_expr();
  measured->range = range_from(begin);
  return measured;
}

DimExpr* Parser::parse_dim_expr() {
  SourceLocation begin = here();
  DimExpr* lhs = parse_dim_term();
  while (at(T::Star) || at(T::Slash)) {
    auto* binary = make<DimBinary>(begin);
    binary->is_division = at(T::Slash);
    binary->op_range = advance().range;
    binary->lhs = lhs;
    binary->rhs = parse_dim_term();
    binary->range = range_from(begin);
    lhs = binary;
  }
  return lhs;
}

DimExpr* Parser::parse_dim_term() {
  SourceLocation begin = here();
  DimExpr* base = parse_dim_primary();
  if (!at(T::Caret)) return base;
  auto* power = make<DimPower>(begin);
  SourceLocation exponent_begin = here();
  advance();
  bool negative = false;
  if (at(T::Minus) || at(T::Plus)) negative = advance().kind == T::Minus;
  const PToken& exponent = peek();
  if (exponent.kind == T::FloatLit || exponent.kind == T::DoubleLit) {
    fail(code::E_SYNTAX, exponent.range,
         "dimension exponents must be integers: rational powers are not part of the language");
  }
  expect(T::IntLit, "an integer exponent", "after '^'");
  int value = 0;
  auto [ptr, ec] = std::from_chars(exponent.text.data(), exponent.text.data() + exponent.text.size(), value);
  if (ec != std::errc{} || ptr != exponent.text.data() + exponent.text.size() || value > 1000) {
    fail(code::E_SYNTAX, exponent.range,
         "dimension exponent '" + std::string(exponent.text) + "' is not a small decimal integer");
  }
  power->base = base;
  power->exponent = negative ? -value : value;
  power->exponent_range = range_from(exponent_begin);
  power->range = range_from(begin);
  return power;
}

DimExpr* Parser::parse_dim_primary() {
  DepthGuard guard(*this);
  SourceLocation begin = here();
  if (at_annotation_name()) {
    auto* name = make<DimName>(begin);
    name->name = std::string(advance().text);
    name->range = range_from(begin);
    return name;
  }
  if (at(T::IntLit)) {
    if (peek().text != "1") {
      fail(code::E_SYNTAX, peek().range,
           "only the literal 1 may appear in a dimension expression, found " + describe(peek()));
    }
    auto* one = make<DimOne>(begin);
    advance();
    one->range = range_from(begin);
    return one;
  }
  if (accept(T::LParen)) {
    auto* paren = make<DimParen>(begin);
    paren->inner = parse_dim_expr();
    expect(T::RParen, "')'", "in dimension expression");
    paren->range = range_from(begin);
    return paren;
  }
  fail_expected("a dimension or space name", "in annotation");
}

}  // namespace safegi::parser_detail
