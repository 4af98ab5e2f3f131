// Declarations: external declarations, qualifiers, type specifiers, structs,
// interface blocks and functions (the annotation syntax: parse_annotation.cpp).

#include <algorithm>

#include <safegi/lexer/extensions.hpp>

#include "parser_impl.hpp"

namespace safegi::parser_detail {

using namespace ast;

namespace {

bool is_word(const PToken& t) {
  return !t.text.empty() && ((t.text[0] >= 'a' && t.text[0] <= 'z') || (t.text[0] >= 'A' && t.text[0] <= 'Z') ||
                             t.text[0] == '_');
}

constexpr std::string_view kAnnotatedTypeWords[] = {"spectrum", "point",    "vector",  "direction", "normal",
                                                    "hpoint",   "map",      "rigidmap", "projmap"};

}  // namespace

bool Parser::is_annotated_type_word(const PToken& token) const {
  if (token.kind != T::Ident) return false;
  if (std::find(std::begin(kAnnotatedTypeWords), std::end(kAnnotatedTypeWords), token.text) ==
      std::end(kAnnotatedTypeWords)) {
    return false;
  }
  const NameKind* own = lookup(token.text);
  if (own == nullptr) return true;
  if (*own == NameKind::Type) return false;  // a program's own type shadows the word
  // A variable of that name (`in normal<object> normal;`) leaves the word a type where only a
  // type can stand: `normal<world> n` and `normal<world>(x)` would otherwise compare a bool.
  if (&token < tokens_.data() || &token >= tokens_.data() + tokens_.size()) return false;
  const std::size_t at = static_cast<std::size_t>(&token - tokens_.data());
  if (at + 1 >= tokens_.size() || tokens_[at + 1].kind != T::Lt) return false;
  const std::size_t end = scan_annotation(at + 1, 0);
  return end != 0 && (tokens_[end].kind == T::Ident || tokens_[end].kind == T::LParen);
}

// ----------------------------------------------------------------- lookahead

std::size_t Parser::scan_brackets(std::size_t i) const {
  int depth = 0;
  for (; i < tokens_.size(); ++i) {
    T k = tokens_[i].kind;
    if (k == T::LBracket || k == T::LParen) ++depth;
    if (k == T::RBracket || k == T::RParen) {
      if (--depth == 0) return i + 1;
    }
    if (k == T::Eof || k == T::Semicolon || k == T::LBrace || k == T::RBrace) return 0;
  }
  return 0;
}

std::size_t Parser::scan_dim_expr(std::size_t i, int nesting) const {
  if (nesting > static_cast<int>(options_.max_nesting)) return 0;
  for (;;) {
    const PToken& t = tokens_[i];
    if (t.kind == T::Ident || t.kind == T::IntLit || (t.kind == T::Unknown && t.reserved)) {
      ++i;
    } else if (t.kind == T::LParen) {
      i = scan_dim_expr(i + 1, nesting + 1);
      if (i == 0 || tokens_[i].kind != T::RParen) return 0;
      ++i;
    } else {
      return 0;
    }
    if (tokens_[i].kind == T::Caret) {
      ++i;
      if (tokens_[i].kind == T::Minus || tokens_[i].kind == T::Plus) ++i;
      if (tokens_[i].kind != T::IntLit) return 0;
      ++i;
    }
    if (tokens_[i].kind != T::Star && tokens_[i].kind != T::Slash) return i;
    ++i;
  }
}

std::size_t Parser::scan_annotation(std::size_t i, int nesting) const {
  if (tokens_[i].kind != T::Lt || nesting > static_cast<int>(options_.max_nesting)) return 0;
  ++i;
  for (;;) {
    const PToken& t = tokens_[i];
    if (t.kind == T::TypeKw || (is_annotated_type_word(t) && tokens_[i + 1].kind == T::Lt)) {
      ++i;
      if (tokens_[i].kind == T::Lt) {
        i = scan_annotation(i, nesting + 1);
        if (i == 0) return 0;
      }
    } else {
      i = scan_dim_expr(i, nesting + 1);
      if (i != 0 && tokens_[i].kind == T::QualKw && tokens_[i].text == "in") i = scan_dim_expr(i + 1, nesting + 1);
      if (i == 0) return 0;
    }
    if (tokens_[i].kind == T::Gt) return i + 1;
    if (tokens_[i].kind != T::Comma) return 0;
    ++i;
  }
}

std::size_t Parser::scan_type_specifier(std::size_t i) const {
  const PToken& t = tokens_[i];
  if (t.kind == T::TypeKw) {
    ++i;
    if (tokens_[i].kind == T::Lt) {
      i = scan_annotation(i, 0);
      if (i == 0) return 0;
    }
  } else if (t.kind == T::Ident) {
    ++i;
    if (is_annotated_type_word(t) && tokens_[i].kind == T::Lt) {
      i = scan_annotation(i, 0);
      if (i == 0) return 0;
    }
  } else {
    return 0;
  }
  while (tokens_[i].kind == T::LBracket) {
    i = scan_brackets(i);
    if (i == 0) return 0;
  }
  return i;
}

bool Parser::at_qualifier() const {
  T k = peek().kind;
  return k == T::QualKw || k == T::Layout || k == T::Subroutine || (k == T::Ident && at_spirv_qualifier());
}

bool Parser::at_declaration() const {
  const PToken& t = peek();
  switch (t.kind) {
    case T::QualKw:
    case T::Layout:
    case T::Subroutine:
    case T::Struct:
    case T::Precision:
      return true;
    case T::TypeKw: {
      std::size_t end = scan_type_specifier(pos_);
      return end != 0 && tokens_[end].kind != T::LParen && tokens_[end].kind != T::Dot;
    }
    case T::Ident: {
      if (peek(1).kind == T::Ident || at_spirv_qualifier() || at_spirv_type()) return true;
      bool annotated = is_annotated_type_word(t) && peek(1).kind == T::Lt;
      if (!annotated && !is_type_name(t.text)) return false;
      std::size_t end = scan_type_specifier(pos_);
      return end != 0 && tokens_[end].kind == T::Ident;
    }
    default:
      return false;
  }
}

bool Parser::at_annotation_declaration() const {
  const PToken& t = peek();
  if (t.kind != T::Ident || !at_annotation_name(1)) return false;
  if (t.text != "dimension" && t.text != "unit" && t.text != "space") return false;
  return !is_type_name(t.text);
}

// ------------------------------------------------------- translation unit

TranslationUnit* Parser::parse_translation_unit() {
  auto* unit = make<TranslationUnit>(here());
  while (!at(T::Eof) && !diagnostics_.limit_reached()) {
    std::size_t start = pos_;
    try {
      parse_external_declaration(unit->decls);
    } catch (const ParseError&) {
      synchronize_global();
      if (pos_ == start) advance();
    }
  }
  unit->range.end = prev_end_;
  return unit;
}

void Parser::parse_external_declaration(std::vector<Decl*>& out) {
  if (at(T::Semicolon)) {
    auto* empty = make<EmptyDecl>(here());
    advance();
    empty->range.end = prev_end_;
    out.push_back(empty);
    return;
  }
  out.push_back(parse_declaration(true));
}

Decl* Parser::parse_declaration(bool global) {
  SourceLocation begin = here();
  std::vector<TemplateParam> template_params;
  SourceRange template_range;
  if (at(T::Template)) {
    if (!global) fail(code::E_SYNTAX, peek().range, "a generic function must be declared at global scope");
    parse_template_header(template_params, template_range);
  } else if (global && at_annotation_declaration()) {
    return parse_annotation_declaration();
  }
  if (at(T::Precision)) {
    auto* decl = make<PrecisionDecl>(begin);
    advance();
    if (!(at(T::QualKw) && peek().qual == QualifierKind::Precision)) {
      fail_expected("'highp', 'mediump' or 'lowp'", "after 'precision'");
    }
    decl->precision = std::string(peek().text);
    decl->precision_range = advance().range;
    decl->type = parse_type_specifier();
    expect_semicolon("after precision statement");
    decl->range = range_from(begin);
    return decl;
  }
  TypeQualifiers qualifiers = parse_qualifiers();
  Decl* decl = parse_declaration_after_qualifiers(std::move(qualifiers), global, std::move(template_params),
                                                  template_range);
  decl->range = range_from(begin);
  return decl;
}

Decl* Parser::parse_declaration_after_qualifiers(TypeQualifiers qualifiers, bool global,
                                                 std::vector<TemplateParam> template_params,
                                                 SourceRange template_range) {
  SourceLocation begin = qualifiers.empty() ? here() : qualifiers.range.begin;
  if (!template_params.empty()) begin = template_range.begin;
  if (!qualifiers.empty() && template_params.empty()) {
    if (at(T::Semicolon)) {  // `layout(local_size_x = 8) in;`
      auto* decl = make<QualifierDecl>(begin);
      decl->qualifiers = std::move(qualifiers);
      advance();
      return decl;
    }
    if (at(T::Ident) && peek(1).kind == T::LBrace) {  // interface block
      auto* block = make<InterfaceBlockDecl>(begin);
      block->qualifiers = std::move(qualifiers);
      block->block_name = std::string(peek().text);
      block->block_name_range = advance().range;
      // GL_EXT_buffer_reference: the block's name is a type (a pointer to the
      // block's memory), already inside its own members (a linked list).
      const bool reference = block->qualifiers.has_layout_id("buffer_reference");
      if (reference) declare(block->block_name, NameKind::Type);
      block->members = parse_member_list("in block", LayoutPlace::BlockMember);
      bool in_out_block = block->qualifiers.has("in") || block->qualifiers.has("out");
      for (const VariableDecl* member : block->members) check_sample(member->qualifiers, in_out_block);
      if (at(T::Ident)) {
        block->instance_name = std::string(peek().text);
        block->instance_name_range = advance().range;
        parse_array_dims(block->instance_array_dims);
        declare(block->instance_name, NameKind::Value);
      } else if (!reference) {
        for (VariableDecl* member : block->members) {
          for (const Declarator& d : member->declarators) declare(d.name, NameKind::Value);
        }
      }
      expect_semicolon("after interface block");
      return block;
    }
    if (at(T::Ident) && (peek(1).kind == T::Comma || peek(1).kind == T::Semicolon) && !is_type_name(peek().text)) {
      auto* decl = make<QualifierDecl>(begin);  // `invariant gl_Position;`, `precise a, b;`
      decl->qualifiers = std::move(qualifiers);
      // `layout(buffer_reference) buffer Node;`: a reference type declared before its block.
      const bool reference = decl->qualifiers.has_layout_id("buffer_reference");
      do {
        const PToken& name = expect(T::Ident, "a name", "in qualifier declaration");
        if (reference) declare(std::string(name.text), NameKind::Type);
        decl->names.emplace_back(name.text);
        decl->name_ranges.push_back(name.range);
      } while (accept(T::Comma));
      expect_semicolon("after qualifier declaration");
      return decl;
    }
  }
  TypeSpecifier* type = parse_type_specifier();
  if (!template_params.empty() && !(at(T::Ident) && peek(1).kind == T::LParen)) {
    fail_expected("a function declaration", "after 'template<...>'");
  }
  if (at(T::Semicolon)) {  // `struct S { ... };`
    auto* decl = make<VariableDecl>(begin);
    decl->qualifiers = std::move(qualifiers);
    decl->type = type;
    advance();
    return decl;
  }
  if (!at(T::Ident)) {
    fail_expected("a name", "after type '" + (type->name.empty() ? std::string("struct") : type->name) + "'");
  }
  if (peek(1).kind == T::LParen) {
    const PToken& name = advance();
    return parse_function_rest(std::move(qualifiers), type, name, begin, std::move(template_params),
                               template_range, global);
  }
  if (global) {
    for (const Qualifier& q : qualifiers.list) {
      if (q.word == "in" || q.word == "out") require(LanguageFeature::global_in_out, q.range);
    }
  }
  check_layout_place(qualifiers, LayoutPlace::Variable);
  check_sample(qualifiers, qualifiers.has("in") || qualifiers.has("out"));
  return parse_init_declarators(std::move(qualifiers), type, begin);
}

// -------------------------------------------------------------- qualifiers

TypeQualifiers Parser::parse_qualifiers() {
  TypeQualifiers qualifiers;
  qualifiers.range = {here(), here()};
  while (at_qualifier()) {
    if (at(T::Layout)) {
      qualifiers.list.push_back(parse_layout_qualifier());
    } else if (at(T::Subroutine)) {
      qualifiers.list.push_back(parse_subroutine_qualifier());
    } else if (at(T::Ident)) {
      qualifiers.list.push_back(parse_spirv_qualifier());
    } else {
      Qualifier q;
      q.kind = peek().qual;
      q.word = std::string(peek().text);
      q.range = advance().range;
      qualifiers.list.push_back(std::move(q));
    }
  }
  qualifiers.range.end = qualifiers.empty() ? qualifiers.range.begin : prev_end_;
  return qualifiers;
}

Qualifier Parser::parse_layout_qualifier() {
  Qualifier q;
  q.kind = QualifierKind::Layout;
  q.word = "layout";
  SourceLocation begin = here();
  advance();
  expect(T::LParen, "'('", "after 'layout'");
  do {
    if (!is_word(peek())) fail_expected("a layout qualifier name", "in 'layout(...)'");
    LayoutId id;
    id.name = std::string(peek().text);
    id.name_range = advance().range;
    if (accept(T::Assign)) id.value = parse_conditional();
    check_layout_id(id);
    q.layout_ids.push_back(std::move(id));
  } while (accept(T::Comma));
  expect(T::RParen, "')'", "to close 'layout('");
  q.range = range_from(begin);
  return q;
}

Qualifier Parser::parse_subroutine_qualifier() {
  Qualifier q;
  q.kind = QualifierKind::Subroutine;
  q.word = "subroutine";
  SourceLocation begin = here();
  advance();
  if (accept(T::LParen)) {
    q.has_type_list = true;
    if (!at(T::RParen)) {
      do {
        q.type_names.emplace_back(expect(T::Ident, "a subroutine type name", "in 'subroutine(...)'").text);
      } while (accept(T::Comma));
    }
    expect(T::RParen, "')'", "to close 'subroutine('");
  }
  q.range = range_from(begin);
  return q;
}

// ------------------------------------------------------------------- types

void Parser::parse_array_dims(std::vector<ArrayDim>& dims, std::size_t outer) {
  while (at(T::LBracket)) {
    ArrayDim dim;
    SourceLocation begin = here();
    advance();
    if (!at(T::RBracket)) dim.size = parse_conditional();
    expect(T::RBracket, "']'", "to close array size");
    dim.range = range_from(begin);
    if (outer + dims.size() == 1) require(LanguageFeature::arrays_of_arrays, dim.range);
    dims.push_back(dim);
  }
}

TypeSpecifier* Parser::parse_type_specifier() {
  SourceLocation begin = here();
  TypeSpecifier* type = parse_type_specifier_nonarray();
  parse_array_dims(type->array_dims);
  type->range = range_from(begin);
  return type;
}

TypeSpecifier* Parser::parse_type_specifier_nonarray() {
  SourceLocation begin = here();
  auto* type = make<TypeSpecifier>(begin);
  if (at(T::Struct)) {
    type->form = TypeSpecifier::Form::Struct;
    type->struct_decl = parse_struct_specifier();
    type->name = type->struct_decl->name;
    type->name_range = type->struct_decl->name_range;
  } else if (at_spirv_type()) {
    return parse_spirv_type();
  } else if (at(T::TypeKw)) {
    type->form = TypeSpecifier::Form::Builtin;
    type->name = std::string(peek().text);
    type->name_range = advance().range;
    if (at(T::Lt)) type->annotation = parse_annotation();
  } else if (at(T::Ident)) {
    bool annotated = is_annotated_type_word(peek()) && peek(1).kind == T::Lt;
    type->form = annotated ? TypeSpecifier::Form::Annotated : TypeSpecifier::Form::Named;
    type->name = std::string(peek().text);
    type->name_range = advance().range;
    if (!annotated && !is_type_name(type->name)) {
      // Reported without unwinding: the declaration still parses, so its
      // names exist and later uses do not cascade.
      Diagnostic d = Diagnostic::error(type->name_range, "unknown type name '" + type->name + "'").with_code(code::E_UNKNOWN_TYPE);
      if (const std::string_view extensions = extensions_declaring_type(type->name); !extensions.empty())
        d.with_hint("'" + type->name + "' is a type only where an extension declares it: #extension " + std::string(extensions));
      diagnostics_.report(std::move(d));
    }
    if (annotated) type->annotation = parse_annotation();
  } else {
    fail_expected("a type", "");
  }
  type->range = range_from(begin);
  return type;
}

StructDecl* Parser::parse_struct_specifier() {
  SourceLocation begin = here();
  auto* decl = make<StructDecl>(begin);
  advance();  // struct
  if (at(T::Ident)) {
    decl->name = std::string(peek().text);
    decl->name_range = advance().range;
  }
  decl->members = parse_member_list("in struct", LayoutPlace::StructMember);
  declare(decl->name, NameKind::Type);
  decl->range = range_from(begin);
  return decl;
}

std::vector<VariableDecl*> Parser::parse_member_list(std::string_view context, LayoutPlace place) {
  DepthGuard guard(*this);
  std::vector<VariableDecl*> members;
  expect(T::LBrace, "'{'", context);
  while (!at(T::RBrace) && !at(T::Eof) && !diagnostics_.limit_reached()) {
    std::size_t start = pos_;
    try {
      SourceLocation begin = here();
      TypeQualifiers qualifiers = parse_qualifiers();
      check_layout_place(qualifiers, place);
      if (place == LayoutPlace::StructMember) check_sample(qualifiers, false);
      TypeSpecifier* type = parse_type_specifier();
      auto* member = make<VariableDecl>(begin);
      member->qualifiers = std::move(qualifiers);
      member->type = type;
      do {
        Declarator d;
        SourceLocation d_begin = here();
        const PToken& name = expect(T::Ident, "a member name", context);
        d.name = std::string(name.text);
        d.name_range = name.range;
        parse_array_dims(d.array_dims, type->array_dims.size());
        d.range = range_from(d_begin);
        member->declarators.push_back(std::move(d));
      } while (accept(T::Comma));
      expect_semicolon("after member declaration");
      member->range = range_from(begin);
      members.push_back(member);
    } catch (const ParseError&) {
      synchronize_statement();
      if (pos_ == start) advance();
    }
  }
  expect(T::RBrace, "'}'", context);
  return members;
}

// --------------------------------------------------- functions and variables

FunctionDecl* Parser::parse_function_rest(TypeQualifiers qualifiers, TypeSpecifier* type, const PToken& name,
                                          SourceLocation begin, std::vector<TemplateParam> template_params,
                                          SourceRange template_range, bool global) {
  auto* fn = make<FunctionDecl>(begin);
  fn->template_params = std::move(template_params);
  fn->template_range = template_range;
  fn->qualifiers = std::move(qualifiers);
  fn->return_type = type;
  fn->name = std::string(name.text);
  fn->name_range = name.range;
  bool subroutine_type = false;
  for (const Qualifier& q : fn->qualifiers.list) {
    subroutine_type |= q.kind == QualifierKind::Subroutine && !q.has_type_list;
  }
  declare(fn->name, subroutine_type ? NameKind::Type : NameKind::Value);

  push_scope();
  struct PopScope {
    Parser& p;
    ~PopScope() { p.pop_scope(); }
  } pop{*this};
  expect(T::LParen, "'('", "after function name");
  if (at(T::TypeKw) && peek().text == "void" && peek(1).kind == T::RParen) {
    advance();
    fn->void_param = true;
  } else if (!at(T::RParen)) {
    do {
      fn->params.push_back(parse_parameter());
    } while (accept(T::Comma));
  }
  expect(T::RParen, "')'", "to close parameter list");
  if (at(T::LBrace)) {
    if (!global) fail(code::E_SYNTAX, peek().range, "a function cannot be defined inside another function");
    fn->body = parse_compound(false);
  } else {
    expect_semicolon("after function prototype");
  }
  fn->range = range_from(begin);
  return fn;
}

ParamDecl* Parser::parse_parameter() {
  SourceLocation begin = here();
  auto* param = make<ParamDecl>(begin);
  param->qualifiers = parse_qualifiers();
  param->type = parse_type_specifier();
  if (at(T::Ident)) {
    param->name = std::string(peek().text);
    param->name_range = advance().range;
    parse_array_dims(param->array_dims, param->type->array_dims.size());
    declare(param->name, NameKind::Value);
  }
  param->range = range_from(begin);
  return param;
}

VariableDecl* Parser::parse_init_declarators(TypeQualifiers qualifiers, TypeSpecifier* type, SourceLocation begin) {
  auto* decl = make<VariableDecl>(begin);
  decl->qualifiers = std::move(qualifiers);
  decl->type = type;
  do {
    Declarator d;
    SourceLocation d_begin = here();
    const PToken& name = expect(T::Ident, "a variable name", "in declaration");
    d.name = std::string(name.text);
    d.name_range = name.range;
    parse_array_dims(d.array_dims, type ? type->array_dims.size() : 0);
    if (accept(T::Assign)) d.initializer = parse_initializer();
    d.range = range_from(d_begin);
    declare(d.name, NameKind::Value);
    decl->declarators.push_back(std::move(d));
  } while (accept(T::Comma));
  expect_semicolon("after declaration");
  return decl;
}

Expr* Parser::parse_initializer(bool top_level) {
  if (!at(T::LBrace)) return parse_assignment();
  DepthGuard guard(*this);
  SourceLocation begin = here();
  auto* list = make<InitializerList>(begin);
  advance();
  std::uint32_t height = 0;
  if (at(T::RBrace)) {  // `= {}`: every member zero (GL_EXT_null_initializer; nested, the checker's error)
    advance();
    list->height = 1;
    list->range = range_from(begin);
    if (top_level) require(LanguageFeature::null_initializer, list->range);
    return list;
  }
  do {
    if (at(T::RBrace) && !list->elements.empty()) {
      list->trailing_comma = true;
      break;
    }
    Expr* element = parse_initializer(false);
    height = std::max(height, element->height);
    list->elements.push_back(element);
  } while (accept(T::Comma));
  expect(T::RBrace, "'}'", "to close initializer list");
  list->height = height + 1;
  list->range = range_from(begin);
  return list;
}

}  // namespace safegi::parser_detail
