#include <algorithm>

#include <safegi/parser/ast.hpp>

namespace safegi::ast {

std::string_view node_kind_name(NodeKind kind) {
  static constexpr std::string_view names[] = {
      "IdentifierExpr", "LiteralExpr",  "UnaryExpr",     "BinaryExpr",     "AssignExpr",    "TernaryExpr",
      "CallExpr",       "IndexExpr",    "MemberExpr",    "MethodCallExpr", "ParenExpr",     "ConvertExpr",   "InitializerList",
      "DimName",        "DimOne",       "DimBinary",     "DimPower",       "DimParen",      "DimUnit",       "TypeSpecifier",
      "Annotation",     "VariableDecl", "QualifierDecl", "FunctionDecl",   "ParamDecl",     "StructDecl",
      "InterfaceBlockDecl", "PrecisionDecl", "DimensionDecl", "UnitDecl",  "SpaceDecl",     "EmptyDecl",
      "CompoundStmt",   "DeclStmt",     "ExprStmt",      "EmptyStmt",      "IfStmt",        "SwitchStmt",
      "CaseLabel",      "DefaultLabel", "WhileStmt",     "DoStmt",         "ForStmt",       "BreakStmt",
      "ContinueStmt",   "DiscardStmt",  "DemoteStmt",    "ReturnStmt",     "TranslationUnit",
  };
  static_assert(std::size(names) == static_cast<std::size_t>(NodeKind::TranslationUnit) + 1);
  return names[static_cast<std::size_t>(kind)];
}

std::string_view unary_op_spelling(UnaryOp op) {
  switch (op) {
    case UnaryOp::Plus: return "+";
    case UnaryOp::Minus: return "-";
    case UnaryOp::Not: return "!";
    case UnaryOp::BitNot: return "~";
    case UnaryOp::PreInc:
    case UnaryOp::PostInc: return "++";
    case UnaryOp::PreDec:
    case UnaryOp::PostDec: return "--";
  }
  return "?";
}

std::string_view binary_op_spelling(BinaryOp op) {
  static constexpr std::string_view spellings[] = {"*",  "/",  "%", "+", "-", "<<", ">>", "<",  ">",  "<=",
                                                   ">=", "==", "!=", "&", "^", "|",  "&&", "^^", "||", ","};
  return spellings[static_cast<std::size_t>(op)];
}

int binary_op_precedence(BinaryOp op) {
  switch (op) {
    case BinaryOp::Mul: case BinaryOp::Div: case BinaryOp::Mod: return 13;
    case BinaryOp::Add: case BinaryOp::Sub: return 12;
    case BinaryOp::Shl: case BinaryOp::Shr: return 11;
    case BinaryOp::Lt: case BinaryOp::Gt: case BinaryOp::Le: case BinaryOp::Ge: return 10;
    case BinaryOp::Eq: case BinaryOp::Ne: return 9;
    case BinaryOp::BitAnd: return 8;
    case BinaryOp::BitXor: return 7;
    case BinaryOp::BitOr: return 6;
    case BinaryOp::LogAnd: return 5;
    case BinaryOp::LogXor: return 4;
    case BinaryOp::LogOr: return 3;
    case BinaryOp::Comma: return 1;
  }
  return 0;
}

std::string_view assign_op_spelling(AssignOp op) {
  static constexpr std::string_view spellings[] = {"=", "*=", "/=", "%=", "+=", "-=", "<<=", ">>=", "&=", "^=", "|="};
  return spellings[static_cast<std::size_t>(op)];
}

std::string_view annotated_type_representation(std::string_view word) {
  if (word == "spectrum" || word == "point" || word == "vector" || word == "direction" || word == "normal") {
    return "vec3";
  }
  if (word == "hpoint") return "vec4";
  if (word == "map" || word == "rigidmap" || word == "projmap") return "mat4";
  return {};
}

bool TypeQualifiers::has(std::string_view word) const {
  return std::any_of(list.begin(), list.end(), [&](const Qualifier& q) { return q.word == word; });
}

bool TypeQualifiers::has_layout_id(std::string_view id) const {
  return std::any_of(list.begin(), list.end(), [&](const Qualifier& q) {
    return std::any_of(q.layout_ids.begin(), q.layout_ids.end(), [&](const LayoutId& l) { return l.name == id; });
  });
}

}  // namespace safegi::ast
