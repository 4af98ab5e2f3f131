// The indented tree dump used by golden tests and the round-trip check.

#include <safegi/parser/printer.hpp>

namespace safegi {
namespace {

using namespace ast;

class Dumper {
 public:
  explicit Dumper(const DumpOptions& options) : options_(options) {}

  std::string take() { return std::move(out_); }

  void node(const Node* n, int level, std::string_view label = {}) {
    if (n == nullptr) return;
    open(level, label, node_kind_name(n->kind), n->range);
    if (const auto* s = dyn_cast<Stmt>(n); s && !s->attributes.empty()) {
      std::string names = "[[";
      for (const StatementAttribute& a : s->attributes) names += (names.size() > 2 ? ", " : "") + a.name;
      text(names + "]]");
    }
    switch (n->kind) {
      case NodeKind::IdentifierExpr: text(static_cast<const IdentifierExpr*>(n)->name); break;
      case NodeKind::LiteralExpr: text(static_cast<const LiteralExpr*>(n)->spelling); break;
      case NodeKind::UnaryExpr: {
        const auto* u = static_cast<const UnaryExpr*>(n);
        text(std::string(unary_op_spelling(u->op)) +
             (u->op == UnaryOp::PostInc || u->op == UnaryOp::PostDec ? " postfix" : ""));
        close();
        node(u->operand, level + 1);
        return;
      }
      case NodeKind::BinaryExpr: {
        const auto* b = static_cast<const BinaryExpr*>(n);
        text(binary_op_spelling(b->op));
        close();
        node(b->lhs, level + 1);
        node(b->rhs, level + 1);
        return;
      }
      case NodeKind::AssignExpr: {
        const auto* a = static_cast<const AssignExpr*>(n);
        text(assign_op_spelling(a->op));
        close();
        node(a->lhs, level + 1);
        node(a->rhs, level + 1);
        return;
      }
      case NodeKind::TernaryExpr: {
        const auto* t = static_cast<const TernaryExpr*>(n);
        close();
        node(t->condition, level + 1);
        node(t->then_expr, level + 1);
        node(t->else_expr, level + 1);
        return;
      }
      case NodeKind::CallExpr: {
        const auto* c = static_cast<const CallExpr*>(n);
        if (!c->callee.empty()) text(c->callee);
        if (c->void_arg) text("(void)");
        close();
        node(c->constructor_type, level + 1, "constructor");
        node(c->callee_expr, level + 1, "callee");
        for (const Expr* a : c->args) node(a, level + 1);
        return;
      }
      case NodeKind::IndexExpr: {
        const auto* i = static_cast<const IndexExpr*>(n);
        close();
        node(i->base, level + 1);
        node(i->index, level + 1);
        return;
      }
      case NodeKind::MemberExpr: {
        const auto* m = static_cast<const MemberExpr*>(n);
        text("." + m->member);
        close();
        node(m->base, level + 1);
        return;
      }
      case NodeKind::MethodCallExpr: {
        const auto* m = static_cast<const MethodCallExpr*>(n);
        text("." + m->method + "()");
        close();
        node(m->base, level + 1);
        for (const Expr* a : m->args) node(a, level + 1);
        return;
      }
      case NodeKind::ParenExpr:
        close();
        node(static_cast<const ParenExpr*>(n)->inner, level + 1);
        return;
      case NodeKind::ConvertExpr: {
        const auto* c = static_cast<const ConvertExpr*>(n);
        text("in");
        close();
        node(c->operand, level + 1);
        node(c->target, level + 1);
        return;
      }
      case NodeKind::InitializerList: {
        const auto* l = static_cast<const InitializerList*>(n);
        close();
        for (const Expr* e : l->elements) node(e, level + 1);
        return;
      }
      case NodeKind::DimName: text(static_cast<const DimName*>(n)->name); break;
      case NodeKind::DimBinary: {
        const auto* b = static_cast<const DimBinary*>(n);
        text(b->is_division ? "/" : "*");
        close();
        node(b->lhs, level + 1);
        node(b->rhs, level + 1);
        return;
      }
      case NodeKind::DimPower: {
        const auto* p = static_cast<const DimPower*>(n);
        text("^" + std::to_string(p->exponent));
        close();
        node(p->base, level + 1);
        return;
      }
      case NodeKind::DimParen:
        close();
        node(static_cast<const DimParen*>(n)->inner, level + 1);
        return;
      case NodeKind::DimUnit: {
        const auto* u = static_cast<const DimUnit*>(n);
        text("in");
        close();
        node(u->dimension, level + 1);
        node(u->unit, level + 1);
        return;
      }
      case NodeKind::TypeSpecifier: {
        const auto* t = static_cast<const TypeSpecifier*>(n);
        static constexpr std::string_view forms[] = {"builtin", "annotated", "named", "struct", "spirv"};
        text(forms[static_cast<int>(t->form)]);
        if (!t->name.empty()) text(t->name);
        close();
        node(t->annotation, level + 1);
        node(t->struct_decl, level + 1);
        dims(t->array_dims, level + 1);
        return;
      }
      case NodeKind::Annotation: {
        close();
        for (const Node* a : static_cast<const Annotation*>(n)->args) node(a, level + 1);
        return;
      }
      case NodeKind::VariableDecl: {
        const auto* v = static_cast<const VariableDecl*>(n);
        qualifiers(v->qualifiers, level);
        close();
        node(v->type, level + 1);
        for (const Declarator& d : v->declarators) declarator(d, level + 1);
        return;
      }
      case NodeKind::QualifierDecl: {
        const auto* q = static_cast<const QualifierDecl*>(n);
        qualifiers(q->qualifiers, level);
        for (const std::string& name : q->names) text(name);
        break;
      }
      case NodeKind::FunctionDecl: {
        const auto* f = static_cast<const FunctionDecl*>(n);
        text(f->name);
        if (f->void_param) text("(void)");
        if (!f->body) text("prototype");
        for (const TemplateParam& p : f->template_params) {
          text(std::string(p.kind == TemplateParamKind::Dimension ? "dimension:" : "space:") + p.name);
        }
        qualifiers(f->qualifiers, level);
        close();
        node(f->return_type, level + 1, "returns");
        for (const ParamDecl* p : f->params) node(p, level + 1);
        node(f->body, level + 1);
        return;
      }
      case NodeKind::ParamDecl: {
        const auto* p = static_cast<const ParamDecl*>(n);
        if (!p->name.empty()) text(p->name);
        qualifiers(p->qualifiers, level);
        close();
        node(p->type, level + 1);
        dims(p->array_dims, level + 1);
        return;
      }
      case NodeKind::StructDecl: {
        const auto* s = static_cast<const StructDecl*>(n);
        if (!s->name.empty()) text(s->name);
        close();
        for (const VariableDecl* m : s->members) node(m, level + 1);
        return;
      }
      case NodeKind::InterfaceBlockDecl: {
        const auto* b = static_cast<const InterfaceBlockDecl*>(n);
        text(b->block_name);
        if (!b->instance_name.empty()) text("instance=" + b->instance_name);
        qualifiers(b->qualifiers, level);
        close();
        for (const VariableDecl* m : b->members) node(m, level + 1);
        dims(b->instance_array_dims, level + 1);
        return;
      }
      case NodeKind::PrecisionDecl: {
        const auto* p = static_cast<const PrecisionDecl*>(n);
        text(p->precision);
        close();
        node(p->type, level + 1);
        return;
      }
      case NodeKind::DimensionDecl: {
        const auto* d = static_cast<const DimensionDecl*>(n);
        text(d->name);
        if (!d->definition) text(d->ratio ? "base ratio" : "base");
        close();
        node(d->definition, level + 1);
        return;
      }
      case NodeKind::UnitDecl: {
        const auto* u = static_cast<const UnitDecl*>(n);
        text(u->name);
        close();
        node(u->dimension, level + 1);
        node(u->scale, level + 1);
        return;
      }
      case NodeKind::SpaceDecl:
        text(static_cast<const SpaceDecl*>(n)->name);
        if (static_cast<const SpaceDecl*>(n)->eye) text("eye");
        if (static_cast<const SpaceDecl*>(n)->frame) text("frame");
        break;
      case NodeKind::CompoundStmt:
        close();
        for (const Stmt* s : static_cast<const CompoundStmt*>(n)->statements) node(s, level + 1);
        return;
      case NodeKind::DeclStmt:
        close();
        node(static_cast<const DeclStmt*>(n)->decl, level + 1);
        return;
      case NodeKind::ExprStmt:
        close();
        node(static_cast<const ExprStmt*>(n)->expr, level + 1);
        return;
      case NodeKind::IfStmt: {
        const auto* i = static_cast<const IfStmt*>(n);
        close();
        attribute_arguments(*i, level + 1);
        node(i->condition, level + 1, "condition");
        node(i->then_stmt, level + 1, "then");
        node(i->else_stmt, level + 1, "else");
        return;
      }
      case NodeKind::SwitchStmt: {
        const auto* s = static_cast<const SwitchStmt*>(n);
        close();
        attribute_arguments(*s, level + 1);
        node(s->selector, level + 1);
        node(s->body, level + 1);
        return;
      }
      case NodeKind::CaseLabel:
        close();
        node(static_cast<const CaseLabel*>(n)->value, level + 1);
        return;
      case NodeKind::WhileStmt: {
        const auto* w = static_cast<const WhileStmt*>(n);
        close();
        attribute_arguments(*w, level + 1);
        condition(w->condition, level + 1);
        node(w->body, level + 1, "body");
        return;
      }
      case NodeKind::DoStmt: {
        const auto* d = static_cast<const DoStmt*>(n);
        close();
        attribute_arguments(*d, level + 1);
        node(d->body, level + 1, "body");
        node(d->condition, level + 1, "condition");
        return;
      }
      case NodeKind::ForStmt: {
        const auto* f = static_cast<const ForStmt*>(n);
        close();
        attribute_arguments(*f, level + 1);
        node(f->init, level + 1, "init");
        condition(f->condition, level + 1);
        node(f->increment, level + 1, "increment");
        node(f->body, level + 1, "body");
        return;
      }
      case NodeKind::ReturnStmt:
        close();
        node(static_cast<const ReturnStmt*>(n)->value, level + 1);
        return;
      case NodeKind::TranslationUnit:
        close();
        for (const Decl* d : static_cast<const TranslationUnit*>(n)->decls) node(d, level + 1);
        return;
      default: break;
    }
    close();
  }

 private:
  void indent(int level) { out_.append(static_cast<std::size_t>(level) * 2, ' '); }
  void open(int level, std::string_view label, std::string_view kind, SourceRange range) {
    indent(level);
    if (!label.empty()) {
      out_ += label;
      out_ += ": ";
    }
    out_ += kind;
    if (options_.ranges) {
      out_ += " @" + std::to_string(range.begin.line) + ":" + std::to_string(range.begin.column) + "-" +
              std::to_string(range.end.line) + ":" + std::to_string(range.end.column);
    }
  }
  void text(std::string_view t) {
    out_ += ' ';
    out_ += t;
  }
  void close() { out_ += '\n'; }

  void attribute_arguments(const Stmt& s, int level) {
    for (const StatementAttribute& a : s.attributes) node(a.argument, level, a.name);
  }

  void qualifiers(const TypeQualifiers& q, int level) {
    (void)level;
    for (const Qualifier& qualifier : q.list) text("[" + print_qualifier(qualifier) + "]");
  }

  void dims(const std::vector<ArrayDim>& list, int level) {
    for (const ArrayDim& d : list) {
      open(level, {}, d.size ? "ArrayDim" : "ArrayDim unsized", d.range);
      close();
      node(d.size, level + 1);
    }
  }

  void declarator(const Declarator& d, int level) {
    open(level, {}, "Declarator", d.range);
    text(d.name);
    close();
    dims(d.array_dims, level + 1);
    node(d.initializer, level + 1, "init");
  }

  void condition(const Condition& c, int level) {
    node(c.expr, level, "condition");
    node(c.decl, level, "condition");
  }

  const DumpOptions& options_;
  std::string out_;
};

}  // namespace

std::string dump_ast(const Node& node, const DumpOptions& options) {
  Dumper dumper(options);
  dumper.node(&node, 0);
  return dumper.take();
}

}  // namespace safegi
