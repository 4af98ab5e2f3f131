#include <safegi/parser/walk.hpp>

namespace safegi::ast {
namespace {

void walk_array_dims(const std::vector<ArrayDim>& dims, const Visitor& visit) {
  for (const ArrayDim& d : dims) walk(d.size, visit);
}

void walk_qualifiers(const TypeQualifiers& q, const Visitor& visit) {
  for (const Qualifier& qual : q.list)
    for (const LayoutId& id : qual.layout_ids) walk(id.value, visit);
}

void walk_condition(const Condition& c, const Visitor& visit) {
  walk(c.expr, visit);
  walk(c.decl, visit);
}

template <class T>
void walk_all(const std::vector<T*>& nodes, const Visitor& visit) {
  for (const T* n : nodes) walk(n, visit);
}

}  // namespace

void walk(const Node* node, const Visitor& visit) {
  if (node == nullptr) return;
  visit(*node);
  if (const auto* s = dyn_cast<Stmt>(node))
    for (const StatementAttribute& a : s->attributes) walk(a.argument, visit);
  switch (node->kind) {
    case NodeKind::IdentifierExpr:
    case NodeKind::LiteralExpr:
    case NodeKind::DimName:
    case NodeKind::DimOne:
    case NodeKind::SpaceDecl:
    case NodeKind::EmptyDecl:
    case NodeKind::EmptyStmt:
    case NodeKind::DefaultLabel:
    case NodeKind::BreakStmt:
    case NodeKind::ContinueStmt:
    case NodeKind::DiscardStmt:
    case NodeKind::DemoteStmt:
      return;
    case NodeKind::UnaryExpr: walk(static_cast<const UnaryExpr*>(node)->operand, visit); return;
    case NodeKind::BinaryExpr: {
      auto* e = static_cast<const BinaryExpr*>(node);
      walk(e->lhs, visit);
      walk(e->rhs, visit);
      return;
    }
    case NodeKind::AssignExpr: {
      auto* e = static_cast<const AssignExpr*>(node);
      walk(e->lhs, visit);
      walk(e->rhs, visit);
      return;
    }
    case NodeKind::TernaryExpr: {
      auto* e = static_cast<const TernaryExpr*>(node);
      walk(e->condition, visit);
      walk(e->then_expr, visit);
      walk(e->else_expr, visit);
      return;
    }
    case NodeKind::CallExpr: {
      auto* e = static_cast<const CallExpr*>(node);
      walk(e->constructor_type, visit);
      walk_all(e->args, visit);
      return;
    }
    case NodeKind::IndexExpr: {
      auto* e = static_cast<const IndexExpr*>(node);
      walk(e->base, visit);
      walk(e->index, visit);
      return;
    }
    case NodeKind::MemberExpr: walk(static_cast<const MemberExpr*>(node)->base, visit); return;
    case NodeKind::MethodCallExpr: {
      auto* e = static_cast<const MethodCallExpr*>(node);
      walk(e->base, visit);
      walk_all(e->args, visit);
      return;
    }
    case NodeKind::ParenExpr: walk(static_cast<const ParenExpr*>(node)->inner, visit); return;
    case NodeKind::ConvertExpr: {
      auto* e = static_cast<const ConvertExpr*>(node);
      walk(e->operand, visit);
      walk(e->target, visit);
      return;
    }
    case NodeKind::InitializerList: walk_all(static_cast<const InitializerList*>(node)->elements, visit); return;
    case NodeKind::DimBinary: {
      auto* e = static_cast<const DimBinary*>(node);
      walk(e->lhs, visit);
      walk(e->rhs, visit);
      return;
    }
    case NodeKind::DimPower: walk(static_cast<const DimPower*>(node)->base, visit); return;
    case NodeKind::DimParen: walk(static_cast<const DimParen*>(node)->inner, visit); return;
    case NodeKind::DimUnit: {
      auto* e = static_cast<const DimUnit*>(node);
      walk(e->dimension, visit);
      walk(e->unit, visit);
      return;
    }
    case NodeKind::TypeSpecifier: {
      auto* t = static_cast<const TypeSpecifier*>(node);
      walk(t->annotation, visit);
      walk(t->struct_decl, visit);
      walk_array_dims(t->array_dims, visit);
      return;
    }
    case NodeKind::Annotation: walk_all(static_cast<const Annotation*>(node)->args, visit); return;
    case NodeKind::VariableDecl: {
      auto* d = static_cast<const VariableDecl*>(node);
      walk_qualifiers(d->qualifiers, visit);
      walk(d->type, visit);
      for (const Declarator& decl : d->declarators) {
        walk_array_dims(decl.array_dims, visit);
        walk(decl.initializer, visit);
      }
      return;
    }
    case NodeKind::QualifierDecl: walk_qualifiers(static_cast<const QualifierDecl*>(node)->qualifiers, visit); return;
    case NodeKind::FunctionDecl: {
      auto* d = static_cast<const FunctionDecl*>(node);
      walk_qualifiers(d->qualifiers, visit);
      walk(d->return_type, visit);
      walk_all(d->params, visit);
      walk(d->body, visit);
      return;
    }
    case NodeKind::ParamDecl: {
      auto* d = static_cast<const ParamDecl*>(node);
      walk_qualifiers(d->qualifiers, visit);
      walk(d->type, visit);
      walk_array_dims(d->array_dims, visit);
      return;
    }
    case NodeKind::StructDecl: walk_all(static_cast<const StructDecl*>(node)->members, visit); return;
    case NodeKind::InterfaceBlockDecl: {
      auto* d = static_cast<const InterfaceBlockDecl*>(node);
      walk_qualifiers(d->qualifiers, visit);
      walk_all(d->members, visit);
      walk_array_dims(d->instance_array_dims, visit);
      return;
    }
    case NodeKind::PrecisionDecl: walk(static_cast<const PrecisionDecl*>(node)->type, visit); return;
    case NodeKind::DimensionDecl: walk(static_cast<const DimensionDecl*>(node)->definition, visit); return;
    case NodeKind::UnitDecl: {
      auto* d = static_cast<const UnitDecl*>(node);
      walk(d->dimension, visit);
      walk(d->scale, visit);
      return;
    }
    case NodeKind::CompoundStmt: walk_all(static_cast<const CompoundStmt*>(node)->statements, visit); return;
    case NodeKind::DeclStmt: walk(static_cast<const DeclStmt*>(node)->decl, visit); return;
    case NodeKind::ExprStmt: walk(static_cast<const ExprStmt*>(node)->expr, visit); return;
    case NodeKind::IfStmt: {
      auto* s = static_cast<const IfStmt*>(node);
      walk(s->condition, visit);
      walk(s->then_stmt, visit);
      walk(s->else_stmt, visit);
      return;
    }
    case NodeKind::SwitchStmt: {
      auto* s = static_cast<const SwitchStmt*>(node);
      walk(s->selector, visit);
      walk(s->body, visit);
      return;
    }
    case NodeKind::CaseLabel: walk(static_cast<const CaseLabel*>(node)->value, visit); return;
    case NodeKind::WhileStmt: {
      auto* s = static_cast<const WhileStmt*>(node);
      walk_condition(s->condition, visit);
      walk(s->body, visit);
      return;
    }
    case NodeKind::DoStmt: {
      auto* s = static_cast<const DoStmt*>(node);
      walk(s->body, visit);
      walk(s->condition, visit);
      return;
    }
    case NodeKind::ForStmt: {
      auto* s = static_cast<const ForStmt*>(node);
      walk(s->init, visit);
      walk_condition(s->condition, visit);
      walk(s->increment, visit);
      walk(s->body, visit);
      return;
    }
    case NodeKind::ReturnStmt: walk(static_cast<const ReturnStmt*>(node)->value, visit); return;
    case NodeKind::TranslationUnit: walk_all(static_cast<const TranslationUnit*>(node)->decls, visit); return;
  }
}

}  // namespace safegi::ast
