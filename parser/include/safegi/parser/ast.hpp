#pragma once
// The syntax tree of SafeGI GLSL (docs/language.md): all of GLSL 4.60 / ES 3.20
// plus the annotation syntax. Every node has the source range it was parsed
// from; annotation syntax has ranges of its own so the elider can blank exactly
// those bytes. Nodes live in an AstContext arena and refer to each other by
// plain pointers that stay valid as long as the context.

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <safegi/diagnostics/source_location.hpp>

namespace safegi::ast {

enum class NodeKind : std::uint8_t {
  // Expressions
  IdentifierExpr,
  LiteralExpr,
  UnaryExpr,
  BinaryExpr,
  AssignExpr,
  TernaryExpr,
  CallExpr,
  IndexExpr,
  MemberExpr,
  MethodCallExpr,
  ParenExpr,
  ConvertExpr,
  InitializerList,
  // Dimension expressions (inside annotations and dimension/unit declarations)
  DimName,
  DimOne,
  DimBinary,
  DimPower,
  DimParen,
  DimUnit,
  // Types
  TypeSpecifier,
  Annotation,
  // Declarations
  VariableDecl,
  QualifierDecl,
  FunctionDecl,
  ParamDecl,
  StructDecl,
  InterfaceBlockDecl,
  PrecisionDecl,
  DimensionDecl,
  UnitDecl,
  SpaceDecl,
  EmptyDecl,
  // Statements
  CompoundStmt,
  DeclStmt,
  ExprStmt,
  EmptyStmt,
  IfStmt,
  SwitchStmt,
  CaseLabel,
  DefaultLabel,
  WhileStmt,
  DoStmt,
  ForStmt,
  BreakStmt,
  ContinueStmt,
  DiscardStmt,
  DemoteStmt,
  ReturnStmt,
  TranslationUnit,
};

std::string_view node_kind_name(NodeKind kind);

struct Node {
  explicit Node(NodeKind k) : kind(k) {}
  virtual ~Node() = default;
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;

  NodeKind kind;
  SourceRange range;
};

// isa / dyn_cast / cast on NodeKind, each node class names its kinds in classof().
template <class T>
bool isa(const Node* node) {
  return node != nullptr && T::classof(node->kind);
}
template <class T>
T* dyn_cast(Node* node) {
  return isa<T>(node) ? static_cast<T*>(node) : nullptr;
}
template <class T>
const T* dyn_cast(const Node* node) {
  return isa<T>(node) ? static_cast<const T*>(node) : nullptr;
}

// ---------------------------------------------------------------- expressions

struct Expr : Node {
  using Node::Node;
  static bool classof(NodeKind k) { return k >= NodeKind::IdentifierExpr && k <= NodeKind::InitializerList; }
  // Height of the expression tree below and including this node. The parser
  // rejects trees higher than ParseOptions::max_expression_height, so later
  // stages may recurse over expressions without a stack check.
  std::uint32_t height = 1;
};

struct IdentifierExpr : Expr {
  IdentifierExpr() : Expr(NodeKind::IdentifierExpr) {}
  static bool classof(NodeKind k) { return k == NodeKind::IdentifierExpr; }
  std::string name;
};

// String: only with GL_EXT_debug_printf (`debugPrintfEXT("x = %f", x)`).
enum class LiteralKind : std::uint8_t { Int, Uint, Float, Double, Bool, String };

struct LiteralExpr : Expr {
  LiteralExpr() : Expr(NodeKind::LiteralExpr) {}
  static bool classof(NodeKind k) { return k == NodeKind::LiteralExpr; }
  LiteralKind literal_kind = LiteralKind::Int;
  std::string spelling;     // as written: "0x1Fu", "1.5e3lf", "true"
  bool is_zero = false;     // the value is zero (literal policy: fits any dimension)
};

enum class UnaryOp : std::uint8_t { Plus, Minus, Not, BitNot, PreInc, PreDec, PostInc, PostDec };
std::string_view unary_op_spelling(UnaryOp op);

struct UnaryExpr : Expr {
  UnaryExpr() : Expr(NodeKind::UnaryExpr) {}
  static bool classof(NodeKind k) { return k == NodeKind::UnaryExpr; }
  UnaryOp op = UnaryOp::Plus;
  SourceRange op_range;
  Expr* operand = nullptr;
};

// Ordered by GLSL precedence groups (see binary_op_precedence).
enum class BinaryOp : std::uint8_t {
  Mul, Div, Mod, Add, Sub, Shl, Shr, Lt, Gt, Le, Ge, Eq, Ne,
  BitAnd, BitXor, BitOr, LogAnd, LogXor, LogOr, Comma,
};
std::string_view binary_op_spelling(BinaryOp op);
// Larger binds tighter: Mul/Div/Mod = 13 … LogOr = 3, Comma = 1.
int binary_op_precedence(BinaryOp op);

struct BinaryExpr : Expr {
  BinaryExpr() : Expr(NodeKind::BinaryExpr) {}
  static bool classof(NodeKind k) { return k == NodeKind::BinaryExpr; }
  BinaryOp op = BinaryOp::Add;
  SourceRange op_range;
  Expr* lhs = nullptr;
  Expr* rhs = nullptr;
};

enum class AssignOp : std::uint8_t { Assign, Mul, Div, Mod, Add, Sub, Shl, Shr, And, Xor, Or };
std::string_view assign_op_spelling(AssignOp op);

struct AssignExpr : Expr {
  AssignExpr() : Expr(NodeKind::AssignExpr) {}
  static bool classof(NodeKind k) { return k == NodeKind::AssignExpr; }
  AssignOp op = AssignOp::Assign;
  SourceRange op_range;
  Expr* lhs = nullptr;
  Expr* rhs = nullptr;
};

struct TernaryExpr : Expr {
  TernaryExpr() : Expr(NodeKind::TernaryExpr) {}
  static bool classof(NodeKind k) { return k == NodeKind::TernaryExpr; }
  Expr* condition = nullptr;
  Expr* then_expr = nullptr;
  Expr* else_expr = nullptr;
};

struct TypeSpecifier;

// A function call (`callee` set) or a constructor (`constructor_type` set:
// `vec3(1.0)`, `float[2](a, b)`, `S(x)`, and casts `float<solid_angle>(x)`),
// or a call through an expression (`callee_expr`: an element of a subroutine
// uniform array, `shade[i](n)`).
struct CallExpr : Expr {
  CallExpr() : Expr(NodeKind::CallExpr) {}
  static bool classof(NodeKind k) { return k == NodeKind::CallExpr; }
  std::string callee;
  SourceRange callee_range;
  TypeSpecifier* constructor_type = nullptr;
  Expr* callee_expr = nullptr;
  std::vector<Expr*> args;
  bool void_arg = false;  // written `f(void)`
};

struct IndexExpr : Expr {
  IndexExpr() : Expr(NodeKind::IndexExpr) {}
  static bool classof(NodeKind k) { return k == NodeKind::IndexExpr; }
  Expr* base = nullptr;
  Expr* index = nullptr;
};

// Field selection and swizzles: `s.field`, `v.xyz`.
struct MemberExpr : Expr {
  MemberExpr() : Expr(NodeKind::MemberExpr) {}
  static bool classof(NodeKind k) { return k == NodeKind::MemberExpr; }
  Expr* base = nullptr;
  std::string member;
  SourceRange member_range;
};

// `a.length()` — the only method GLSL has.
struct MethodCallExpr : Expr {
  MethodCallExpr() : Expr(NodeKind::MethodCallExpr) {}
  static bool classof(NodeKind k) { return k == NodeKind::MethodCallExpr; }
  Expr* base = nullptr;
  std::string method;
  SourceRange method_range;
  std::vector<Expr*> args;
};

struct ParenExpr : Expr {
  ParenExpr() : Expr(NodeKind::ParenExpr) {}
  static bool classof(NodeKind k) { return k == NodeKind::ParenExpr; }
  Expr* inner = nullptr;
};

// The expression inside any parentheses around it.
inline const Expr* without_parens(const Expr* e) {
  while (e != nullptr && e->kind == NodeKind::ParenExpr) e = static_cast<const ParenExpr*>(e)->inner;
  return e;
}

struct DimExpr;

// `p in world`, `d in centimeter`, `v in (kilometer / hour)` (docs/language.md,
// "Conversions"): a value converted to another space, through the program's
// maps, or to another unit, by a constant factor. Binds tighter than `*` and
// looser than unary operators: `a * b in world` is `a * (b in world)`.
struct ConvertExpr : Expr {
  ConvertExpr() : Expr(NodeKind::ConvertExpr) {}
  static bool classof(NodeKind k) { return k == NodeKind::ConvertExpr; }
  Expr* operand = nullptr;
  SourceRange in_range;       // the word `in`
  DimExpr* target = nullptr;  // a DimName, or a DimParen around a unit expression
};

// `{a, b, {c, d}}` initialisers (GLSL 4.20).
struct InitializerList : Expr {
  InitializerList() : Expr(NodeKind::InitializerList) {}
  static bool classof(NodeKind k) { return k == NodeKind::InitializerList; }
  std::vector<Expr*> elements;
  bool trailing_comma = false;
};

// ----------------------------------------------------- dimension expressions

struct DimExpr : Node {
  using Node::Node;
  static bool classof(NodeKind k) { return k >= NodeKind::DimName && k <= NodeKind::DimUnit; }
};

// A dimension name, or a space name when it stands alone in an annotation.
struct DimName : DimExpr {
  DimName() : DimExpr(NodeKind::DimName) {}
  static bool classof(NodeKind k) { return k == NodeKind::DimName; }
  std::string name;
};

// The literal `1`: the dimensionless dimension.
struct DimOne : DimExpr {
  DimOne() : DimExpr(NodeKind::DimOne) {}
  static bool classof(NodeKind k) { return k == NodeKind::DimOne; }
};

struct DimBinary : DimExpr {
  DimBinary() : DimExpr(NodeKind::DimBinary) {}
  static bool classof(NodeKind k) { return k == NodeKind::DimBinary; }
  bool is_division = false;  // `/`, else `*`
  SourceRange op_range;
  DimExpr* lhs = nullptr;
  DimExpr* rhs = nullptr;
};

// `base ^ exponent`, integer exponents only.
struct DimPower : DimExpr {
  DimPower() : DimExpr(NodeKind::DimPower) {}
  static bool classof(NodeKind k) { return k == NodeKind::DimPower; }
  DimExpr* base = nullptr;
  std::int32_t exponent = 1;
  SourceRange exponent_range;  // from `^` through the integer
};

struct DimParen : DimExpr {
  DimParen() : DimExpr(NodeKind::DimParen) {}
  static bool classof(NodeKind k) { return k == NodeKind::DimParen; }
  DimExpr* inner = nullptr;
};

// `length in centimeter`, `area in centimeter^2` as an annotation argument: a
// dimension measured in a unit (a product of powers of unit names).
struct DimUnit : DimExpr {
  DimUnit() : DimExpr(NodeKind::DimUnit) {}
  static bool classof(NodeKind k) { return k == NodeKind::DimUnit; }
  DimExpr* dimension = nullptr;
  SourceRange in_range;  // the word `in`
  DimExpr* unit = nullptr;
};

// ---------------------------------------------------------------------- types

// `[N]` or `[]` on a type or a declarator.
struct ArrayDim {
  Expr* size = nullptr;  // nullptr: unsized
  SourceRange range;     // brackets included
};

// `< arg, ... >` after a type name. Each argument is a DimExpr (a dimension
// expression, or a lone name that may denote a space) or a TypeSpecifier
// (the texel type of a sampler).
struct Annotation : Node {
  Annotation() : Node(NodeKind::Annotation) {}
  static bool classof(NodeKind k) { return k == NodeKind::Annotation; }
  std::vector<Node*> args;  // DimExpr* or TypeSpecifier*
};

struct StructDecl;
struct TypeSpecifier;

// One argument of a GL_EXT_spirv_intrinsics qualifier or type (`spirv_decorate(...)`,
// `spirv_type(...)`): `extensions = ["…", …]`, `capabilities = [n, …]`, `set = "…"`, `id = n`,
// a literal or constant expression (an identifier in spirv_decorate_id), or a type name (spirv_type).
struct SpirvArg {
  enum class Kind : std::uint8_t { Extensions, Capabilities, Set, Id, Value, Type };
  Kind kind = Kind::Value;
  SourceRange range;
  std::vector<Expr*> list;  // Extensions, Capabilities
  Expr* value = nullptr;    // Set, Id, Value
  TypeSpecifier* type = nullptr;  // Type
};

// The GLSL type an annotated type word stands for (docs/language.md):
// "point" -> "vec3", "hpoint" -> "vec4", "map" -> "mat4", ...; empty when
// `word` is not one of spectrum point vector direction normal hpoint map
// rigidmap projmap.
std::string_view annotated_type_representation(std::string_view word);

struct TypeSpecifier : Node {
  TypeSpecifier() : Node(NodeKind::TypeSpecifier) {}
  static bool classof(NodeKind k) { return k == NodeKind::TypeSpecifier; }

  enum class Form : std::uint8_t {
    Builtin,    // a GLSL type keyword: float, vec3, sampler2DShadow, void, ...
    Annotated,  // a SafeGI annotated type word: spectrum, point, map, ...
    Named,      // a user struct name
    Struct,     // an inline struct specifier (`struct S { ... }`)
    Spirv,      // `spirv_type(...)` (GL_EXT_spirv_intrinsics): opaque; `name` is its canonical spelling
  };
  Form form = Form::Builtin;
  std::string name;            // empty for an anonymous inline struct
  SourceRange name_range;
  Annotation* annotation = nullptr;
  StructDecl* struct_decl = nullptr;  // Form::Struct
  std::vector<ArrayDim> array_dims;   // `float[3][2]`
  std::vector<SpirvArg> spirv_args;   // Form::Spirv
};

// ----------------------------------------------------------------- qualifiers

enum class QualifierKind : std::uint8_t {
  Storage,        // const in out inout attribute varying uniform buffer shared centroid sample patch
  Layout,         // layout(...)
  Precision,      // highp mediump lowp
  Interpolation,  // smooth flat noperspective
  Invariant,
  Precise,
  Memory,         // coherent volatile restrict readonly writeonly (and *coherent, nonprivate)
  Subroutine,     // subroutine, subroutine(T1, T2)
  // GL_EXT_spirv_intrinsics: spirv_decorate, spirv_decorate_id, spirv_decorate_string,
  // spirv_storage_class, spirv_execution_mode, spirv_execution_mode_id, spirv_instruction
  // (each with an argument list), spirv_by_reference, spirv_literal.
  Spirv,
};

struct LayoutId {
  std::string name;
  SourceRange name_range;
  Expr* value = nullptr;  // `name = value`, else nullptr
};

struct Qualifier {
  QualifierKind kind = QualifierKind::Storage;
  std::string word;  // the keyword as written ("layout", "uniform", ...)
  SourceRange range;
  std::vector<LayoutId> layout_ids;         // Layout
  std::vector<std::string> type_names;      // Subroutine with a type list
  bool has_type_list = false;               // `subroutine(...)` even if empty
  std::vector<SpirvArg> spirv_args;         // Spirv with an argument list
  std::string spirv_text;                   // Spirv: the canonical spelling, `spirv_decorate(11, 4992)`
};

struct TypeQualifiers {
  std::vector<Qualifier> list;
  SourceRange range;
  bool empty() const { return list.empty(); }
  bool has(std::string_view word) const;
  bool has_layout_id(std::string_view id) const;  // `layout(..., id, ...)` in any layout qualifier
};

// --------------------------------------------------------------- declarations

struct Decl : Node {
  using Node::Node;
  static bool classof(NodeKind k) { return k >= NodeKind::VariableDecl && k <= NodeKind::EmptyDecl; }
};

struct Declarator {
  std::string name;
  SourceRange name_range;
  std::vector<ArrayDim> array_dims;
  Expr* initializer = nullptr;
  SourceRange range;  // name through initializer
};

// `quals type a = 1, b[2];`, struct members, block members, and a struct
// definition without declarators (`struct S { ... };`).
struct VariableDecl : Decl {
  VariableDecl() : Decl(NodeKind::VariableDecl) {}
  static bool classof(NodeKind k) { return k == NodeKind::VariableDecl; }
  TypeQualifiers qualifiers;
  TypeSpecifier* type = nullptr;
  std::vector<Declarator> declarators;
};

// Qualifiers without a type: `invariant gl_Position;`, `layout(local_size_x = 8) in;`,
// `precise p;`, `layout(std140) uniform;`.
struct QualifierDecl : Decl {
  QualifierDecl() : Decl(NodeKind::QualifierDecl) {}
  static bool classof(NodeKind k) { return k == NodeKind::QualifierDecl; }
  TypeQualifiers qualifiers;
  std::vector<std::string> names;
  std::vector<SourceRange> name_ranges;
};

struct ParamDecl : Decl {
  ParamDecl() : Decl(NodeKind::ParamDecl) {}
  static bool classof(NodeKind k) { return k == NodeKind::ParamDecl; }
  TypeQualifiers qualifiers;
  TypeSpecifier* type = nullptr;
  std::string name;  // may be empty in a prototype
  SourceRange name_range;
  std::vector<ArrayDim> array_dims;
};

enum class TemplateParamKind : std::uint8_t { Dimension, Space };

struct TemplateParam {
  TemplateParamKind kind = TemplateParamKind::Dimension;
  std::string name;
  SourceRange name_range;
  SourceRange range;  // `dimension D`
};

struct CompoundStmt;

struct FunctionDecl : Decl {
  FunctionDecl() : Decl(NodeKind::FunctionDecl) {}
  static bool classof(NodeKind k) { return k == NodeKind::FunctionDecl; }
  std::vector<TemplateParam> template_params;  // empty: not generic
  SourceRange template_range;                  // `template< ... >`
  TypeQualifiers qualifiers;                   // on the return type
  TypeSpecifier* return_type = nullptr;
  std::string name;
  SourceRange name_range;
  std::vector<ParamDecl*> params;
  bool void_param = false;        // written `f(void)`
  CompoundStmt* body = nullptr;   // nullptr: a prototype
};

struct StructDecl : Decl {
  StructDecl() : Decl(NodeKind::StructDecl) {}
  static bool classof(NodeKind k) { return k == NodeKind::StructDecl; }
  std::string name;  // empty: anonymous
  SourceRange name_range;
  std::vector<VariableDecl*> members;
};

// `quals BlockName { members } instance[dims];`
struct InterfaceBlockDecl : Decl {
  InterfaceBlockDecl() : Decl(NodeKind::InterfaceBlockDecl) {}
  static bool classof(NodeKind k) { return k == NodeKind::InterfaceBlockDecl; }
  TypeQualifiers qualifiers;
  std::string block_name;
  SourceRange block_name_range;
  std::vector<VariableDecl*> members;
  std::string instance_name;  // empty: members are global names
  SourceRange instance_name_range;
  std::vector<ArrayDim> instance_array_dims;
};

// `precision highp float;`
struct PrecisionDecl : Decl {
  PrecisionDecl() : Decl(NodeKind::PrecisionDecl) {}
  static bool classof(NodeKind k) { return k == NodeKind::PrecisionDecl; }
  std::string precision;
  SourceRange precision_range;
  TypeSpecifier* type = nullptr;
};

// `dimension length;` / `dimension area = length^2;`
struct DimensionDecl : Decl {
  DimensionDecl() : Decl(NodeKind::DimensionDecl) {}
  static bool classof(NodeKind k) { return k == NodeKind::DimensionDecl; }
  std::string name;
  SourceRange name_range;
  DimExpr* definition = nullptr;  // nullptr: a base dimension
  bool ratio = false;             // `dimension angle : ratio;`: a base whose values are ratios
};

// `unit centimeter : length = 0.01;`
struct UnitDecl : Decl {
  UnitDecl() : Decl(NodeKind::UnitDecl) {}
  static bool classof(NodeKind k) { return k == NodeKind::UnitDecl; }
  std::string name;
  SourceRange name_range;
  DimExpr* dimension = nullptr;
  Expr* scale = nullptr;
};

// `space world;`
struct SpaceDecl : Decl {
  SpaceDecl() : Decl(NodeKind::SpaceDecl) {}
  static bool classof(NodeKind k) { return k == NodeKind::SpaceDecl; }
  std::string name;
  SourceRange name_range;
  bool eye = false;    // `space view : eye;`: the space's origin is the eye
  bool frame = false;  // `space shading : frame;`: a local frame whose z axis is the surface normal
};

// A stray `;` at global scope.
struct EmptyDecl : Decl {
  EmptyDecl() : Decl(NodeKind::EmptyDecl) {}
  static bool classof(NodeKind k) { return k == NodeKind::EmptyDecl; }
};

// ----------------------------------------------------------------- statements

// `[[unroll]]`, `[[dependency_length(4)]]`: an attribute of GL_EXT_control_flow_attributes,
// written before a loop, an if or a switch.
struct StatementAttribute {
  std::string name;
  SourceRange name_range;
  Expr* argument = nullptr;  // the constant of `name(argument)`, or none
};

struct Stmt : Node {
  using Node::Node;
  static bool classof(NodeKind k) { return k >= NodeKind::CompoundStmt && k <= NodeKind::ReturnStmt; }
  // Only on IfStmt, SwitchStmt, WhileStmt, DoStmt and ForStmt; `range` starts at the keyword,
  // `attributes_range` covers `[[ ... ]]`.
  std::vector<StatementAttribute> attributes;
  SourceRange attributes_range;
};

struct CompoundStmt : Stmt {
  CompoundStmt() : Stmt(NodeKind::CompoundStmt) {}
  static bool classof(NodeKind k) { return k == NodeKind::CompoundStmt; }
  std::vector<Stmt*> statements;
};

struct DeclStmt : Stmt {
  DeclStmt() : Stmt(NodeKind::DeclStmt) {}
  static bool classof(NodeKind k) { return k == NodeKind::DeclStmt; }
  Decl* decl = nullptr;  // VariableDecl, QualifierDecl, PrecisionDecl, or a local prototype
};

struct ExprStmt : Stmt {
  ExprStmt() : Stmt(NodeKind::ExprStmt) {}
  static bool classof(NodeKind k) { return k == NodeKind::ExprStmt; }
  Expr* expr = nullptr;
};

struct EmptyStmt : Stmt {
  EmptyStmt() : Stmt(NodeKind::EmptyStmt) {}
  static bool classof(NodeKind k) { return k == NodeKind::EmptyStmt; }
};

struct IfStmt : Stmt {
  IfStmt() : Stmt(NodeKind::IfStmt) {}
  static bool classof(NodeKind k) { return k == NodeKind::IfStmt; }
  Expr* condition = nullptr;
  Stmt* then_stmt = nullptr;
  Stmt* else_stmt = nullptr;
};

struct SwitchStmt : Stmt {
  SwitchStmt() : Stmt(NodeKind::SwitchStmt) {}
  static bool classof(NodeKind k) { return k == NodeKind::SwitchStmt; }
  Expr* selector = nullptr;
  CompoundStmt* body = nullptr;
};

struct CaseLabel : Stmt {
  CaseLabel() : Stmt(NodeKind::CaseLabel) {}
  static bool classof(NodeKind k) { return k == NodeKind::CaseLabel; }
  Expr* value = nullptr;
};

struct DefaultLabel : Stmt {
  DefaultLabel() : Stmt(NodeKind::DefaultLabel) {}
  static bool classof(NodeKind k) { return k == NodeKind::DefaultLabel; }
};

// A loop condition is an expression or a declaration `type name = init`.
struct Condition {
  Expr* expr = nullptr;
  VariableDecl* decl = nullptr;
  bool present() const { return expr != nullptr || decl != nullptr; }
};

struct WhileStmt : Stmt {
  WhileStmt() : Stmt(NodeKind::WhileStmt) {}
  static bool classof(NodeKind k) { return k == NodeKind::WhileStmt; }
  Condition condition;
  Stmt* body = nullptr;
};

struct DoStmt : Stmt {
  DoStmt() : Stmt(NodeKind::DoStmt) {}
  static bool classof(NodeKind k) { return k == NodeKind::DoStmt; }
  Stmt* body = nullptr;
  Expr* condition = nullptr;
};

struct ForStmt : Stmt {
  ForStmt() : Stmt(NodeKind::ForStmt) {}
  static bool classof(NodeKind k) { return k == NodeKind::ForStmt; }
  Stmt* init = nullptr;     // DeclStmt, ExprStmt or EmptyStmt
  Condition condition;      // may be absent
  Expr* increment = nullptr;
  Stmt* body = nullptr;
};

// break, continue, discard, demote: the kind says which.
struct JumpStmt : Stmt {
  explicit JumpStmt(NodeKind k = NodeKind::BreakStmt) : Stmt(k) {}
  static bool classof(NodeKind k) { return k >= NodeKind::BreakStmt && k <= NodeKind::DemoteStmt; }
};

struct ReturnStmt : Stmt {
  ReturnStmt() : Stmt(NodeKind::ReturnStmt) {}
  static bool classof(NodeKind k) { return k == NodeKind::ReturnStmt; }
  Expr* value = nullptr;
};

struct TranslationUnit : Node {
  TranslationUnit() : Node(NodeKind::TranslationUnit) {}
  static bool classof(NodeKind k) { return k == NodeKind::TranslationUnit; }
  std::vector<Decl*> decls;
};

// ------------------------------------------------------------------- context

// Owns the nodes of one parse. Nodes are destroyed together, without
// recursion, so arbitrarily deep trees are freed safely.
class AstContext {
 public:
  template <class T, class... Args>
  T* make(Args&&... args) {
    auto node = std::make_unique<T>(std::forward<Args>(args)...);
    T* raw = node.get();
    nodes_.push_back(std::move(node));
    return raw;
  }
  std::size_t node_count() const { return nodes_.size(); }

 private:
  std::vector<std::unique_ptr<Node>> nodes_;
};

}  // namespace safegi::ast
