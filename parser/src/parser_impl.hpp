#pragma once
// The recursive-descent parser. Split over parse_decl.cpp (external and
// local declarations, qualifiers, types, annotations), parse_stmt.cpp and
// parse_expr.cpp. Errors throw ParseError after reporting; declaration and
// statement loops catch it and resynchronise, so one mistake gives one
// diagnostic.

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <safegi/diagnostics/codes.hpp>
#include <safegi/diagnostics/diagnostic.hpp>
#include <safegi/parser/ast.hpp>
#include <safegi/parser/parser.hpp>

#include "ptoken.hpp"

namespace safegi::parser_detail {

struct ParseError {};

class Parser {
 public:
  Parser(std::vector<PToken> tokens, DiagnosticEngine& diagnostics, const ParseOptions& options,
         ast::AstContext& context);

  ast::TranslationUnit* parse_translation_unit();

 private:
  // Where a layout qualifier stands (check_layout_place).
  enum class LayoutPlace : std::uint8_t { Variable, StructMember, BlockMember };
  // ------------------------------------------------------------ token access
  const PToken& peek(std::size_t ahead = 0) const {
    std::size_t i = pos_ + ahead;
    return i < tokens_.size() ? tokens_[i] : tokens_.back();
  }
  bool at(T kind) const { return peek().kind == kind; }
  const PToken& advance() {
    const PToken& t = tokens_[pos_];
    if (pos_ + 1 < tokens_.size()) ++pos_;
    prev_end_ = t.range.end;
    return t;
  }
  bool accept(T kind) {
    if (!at(kind)) return false;
    advance();
    return true;
  }
  const PToken& expect(T kind, std::string_view what, std::string_view context);
  void expect_semicolon(std::string_view context);
  // Reports an error with its code (codes.def) and unwinds to the enclosing recovery point.
  [[noreturn]] void fail(const char* code, SourceRange range, std::string message);
  [[noreturn]] void fail_expected(std::string_view what, std::string_view context);
  SourceRange range_from(SourceLocation begin) const { return {begin, prev_end_}; }
  SourceLocation here() const { return peek().range.begin; }

  // ------------------------------------------------------------- scopes
  enum class NameKind : std::uint8_t { Type, Value };
  void push_scope() { scopes_.emplace_back(); }
  void pop_scope() { scopes_.pop_back(); }
  void declare(std::string_view name, NameKind kind);
  const NameKind* lookup(std::string_view name) const;
  bool is_type_name(std::string_view name) const;
  bool is_annotated_type_word(const PToken& token) const;  // a SafeGI type word not shadowed

  // ------------------------------------------------------------ recursion limit
  // One level of nesting (ParseOptions::max_nesting): taken exactly where the
  // parser recurses into a nested construct — a block, an unbraced statement
  // body, parentheses (grouping, calls, constructors), index brackets, an
  // initializer-list brace, a struct or block member list, an annotation, an
  // operand of a prefix operator, the right side of an assignment, the arms of
  // `?:`. So N nested parentheses are N levels.
  struct DepthGuard {
    Parser& parser;
    explicit DepthGuard(Parser& p);
    ~DepthGuard() { --parser.depth_; }
  };
  // Several levels taken one by one in a loop (a chain of prefix operators or
  // assignments), all released at the end of the scope.
  struct NestingLevels {
    Parser& parser;
    unsigned taken = 0;
    explicit NestingLevels(Parser& p) : parser(p) {}
    void add();
    ~NestingLevels() { parser.depth_ -= taken; }
  };
  void enter_level();  // one more level, or the "nesting too deep" error

  // ---------------------------------------------------- declarations (parse_decl.cpp)
  void parse_external_declaration(std::vector<ast::Decl*>& out);
  ast::Decl* parse_declaration(bool global);  // after qualifiers/type lookahead decided it is one
  ast::Decl* parse_declaration_after_qualifiers(ast::TypeQualifiers qualifiers, bool global,
                                               std::vector<ast::TemplateParam> template_params,
                                               SourceRange template_range);
  ast::Decl* parse_annotation_declaration();
  bool at_annotation_declaration() const;
  // A name a dimension, unit or space may have: an identifier, or a word GLSL only reserves.
  bool at_annotation_name(std::size_t offset = 0) const {
    return peek(offset).kind == T::Ident || (peek(offset).kind == T::Unknown && peek(offset).reserved);
  }
  void parse_template_header(std::vector<ast::TemplateParam>& params, SourceRange& range);
  ast::TypeQualifiers parse_qualifiers();
  bool at_qualifier() const;
  ast::Qualifier parse_layout_qualifier();
  ast::Qualifier parse_subroutine_qualifier();
  ast::TypeSpecifier* parse_type_specifier();
  ast::TypeSpecifier* parse_type_specifier_nonarray();
  ast::StructDecl* parse_struct_specifier();
  std::vector<ast::VariableDecl*> parse_member_list(std::string_view context, LayoutPlace place);
  ast::Annotation* parse_annotation();
  ast::Node* parse_annotation_arg();
  ast::DimExpr* parse_dim_expr();
  ast::DimExpr* parse_dim_term();
  ast::DimExpr* parse_dim_primary();
  // `outer`: dimensions the declaration already has (from its type), for the
  // arrays-of-arrays gate.
  void parse_array_dims(std::vector<ast::ArrayDim>& dims, std::size_t outer = 0);
  // Reports `feature` at `where` when ParseOptions::language does not allow it.
  void require(LanguageFeature feature, SourceRange where);
  // Layout identifiers of later versions and non-literal layout values.
  void check_layout_id(const ast::LayoutId& id);
  // Block layouts where no block is: packing (std140, std430, shared, packed)
  // on a variable or any member, matrix order (row_major, column_major) on a
  // variable or a struct member.
  void check_layout_place(const ast::TypeQualifiers& qualifiers, LayoutPlace place);
  // `sample` qualifies only shader inputs and outputs, never with `centroid`;
  // `in_out` says whether this declaration is one.
  void check_sample(const ast::TypeQualifiers& qualifiers, bool in_out);
  ast::FunctionDecl* parse_function_rest(ast::TypeQualifiers qualifiers, ast::TypeSpecifier* type,
                                         const PToken& name, SourceLocation begin,
                                         std::vector<ast::TemplateParam> template_params,
                                         SourceRange template_range, bool global);
  ast::ParamDecl* parse_parameter();
  ast::VariableDecl* parse_init_declarators(ast::TypeQualifiers qualifiers, ast::TypeSpecifier* type,
                                            SourceLocation begin);
  // `top_level`: the whole initializer of a declarator, where `{}` (GL_EXT_null_initializer) stands.
  ast::Expr* parse_initializer(bool top_level = true);

  // Lookahead: does a type specifier start here (and where does it end)?
  // Returns the index after it, or 0 when there is none. Never reports.
  std::size_t scan_type_specifier(std::size_t at) const;
  std::size_t scan_annotation(std::size_t at, int nesting) const;
  std::size_t scan_dim_expr(std::size_t at, int nesting) const;
  std::size_t scan_brackets(std::size_t at) const;
  bool at_declaration() const;  // in a statement context

  // ---------------------------------------- GL_EXT_spirv_intrinsics (parse_spirv.cpp)
  bool spirv_enabled() const;
  // A spirv_* qualifier starts here (spirv_decorate(…), spirv_by_reference, …), or spirv_type(…).
  bool at_spirv_qualifier() const;
  bool at_spirv_type() const;
  void require_spirv(const PToken& word);  // the extension's error when it is not enabled
  ast::Qualifier parse_spirv_qualifier();
  ast::TypeSpecifier* parse_spirv_type();
  std::vector<ast::SpirvArg> parse_spirv_args(std::string_view word);
  void check_spirv_value(std::string_view word, std::size_t index, const PToken& first, const ast::Expr* value,
                         const std::string& context);
  std::string spirv_spelling(std::size_t first) const;  // tokens [first, pos_) as one canonical text

  // ------------------------------------------------------- statements (parse_stmt.cpp)
  ast::Stmt* parse_statement();
  ast::Stmt* parse_substatement();  // the body of a control statement
  ast::Stmt* parse_statement_or_recover();
  ast::CompoundStmt* parse_compound(bool new_scope);
  ast::Stmt* parse_simple_statement();
  ast::Stmt* parse_if();
  ast::Stmt* parse_switch();
  ast::Stmt* parse_while();
  ast::Stmt* parse_do();
  ast::Stmt* parse_for();
  ast::Condition parse_condition();
  ast::Stmt* parse_jump();
  // `[[unroll]] for (...)`: attributes (GL_EXT_control_flow_attributes), then the loop, if or switch.
  ast::Stmt* parse_attributed_statement();
  void synchronize_statement();
  void synchronize_global();

  // ------------------------------------------------------ expressions (parse_expr.cpp)
  ast::Expr* parse_expression();  // with commas
  ast::Expr* parse_assignment();
  ast::Expr* parse_conditional();
  ast::Expr* parse_binary(int min_precedence);
  ast::Expr* parse_unary();
  // A unary expression followed by any number of `in target` conversions.
  ast::Expr* parse_conversion();
  bool at_conversion() const;
  bool at_in(std::size_t offset = 0) const;
  ast::Expr* parse_postfix();
  ast::Expr* parse_primary();
  ast::Expr* parse_call_args(ast::CallExpr* call);
  std::vector<ast::Expr*> parse_method_args();
  ast::Expr* finish_expr(ast::Expr* e, SourceLocation begin);
  bool binary_op_here(ast::BinaryOp& op, int& token_count) const;
  bool assign_op_here(ast::AssignOp& op, int& token_count) const;
  bool prefix_op_here(ast::UnaryOp& op) const;
  void check_height(ast::Expr* e);
  ast::LiteralExpr* make_literal(const PToken& token);

  template <class N>
  N* make(SourceLocation begin) {
    N* n = context_.make<N>();
    n->range = {begin, begin};
    return n;
  }

  std::vector<PToken> tokens_;
  std::size_t pos_ = 0;
  SourceLocation prev_end_;
  DiagnosticEngine& diagnostics_;
  ParseOptions options_;
  ast::AstContext& context_;
  std::vector<std::unordered_map<std::string, NameKind>> scopes_;
  unsigned depth_ = 0;
  unsigned conditional_depth_ = 0;  // `?:` arms being parsed (parse_conditional)
  bool depth_reported_ = false;
  bool eof_reported_ = false;
};

}  // namespace safegi::parser_detail
