// GLSL back from the tree. Parenthesised source keeps its ParenExpr nodes, so
// a parsed tree prints without extra parentheses; trees built by hand get the
// parentheses precedence needs.

#include <unordered_map>

#include <safegi/parser/printer.hpp>

namespace safegi {
namespace {

using namespace ast;

class GlslPrinter {
 public:
  explicit GlslPrinter(const PrintOptions& options) : options_(options) {}

  std::string print_unit(const TranslationUnit& unit) {
    out_ += options_.preamble;
    for (const Decl* d : unit.decls) {
      if (const auto* u = dyn_cast<UnitDecl>(d)) units_[u->name] = u->scale;
    }
    for (const Decl* d : unit.decls) declaration(*d, true);
    return std::move(out_);
  }

  void expression(const Expr& e, int parent_precedence = 0);
  void type(const TypeSpecifier& t);
  void qualifier(const Qualifier& q);

  std::string take() { return std::move(out_); }

 private:
  void line_start() {
    if (suppress_indent_) {
      suppress_indent_ = false;
      return;
    }
    for (int i = 0; i < level_; ++i) out_ += options_.indent;
  }
  void declaration(const Decl& d, bool top_level);
  void qualifiers(const TypeQualifiers& q);
  void array_dims(const std::vector<ArrayDim>& dims);
  void annotation(const Annotation& a);
  void dim(const Node& n);
  void members(const std::vector<VariableDecl*>& list);
  void variable_decl_inline(const VariableDecl& v);  // no ';'
  void statement(const Stmt& s);
  void statement_inline(const Stmt& s);  // for-init: no indentation, no newline
  void sub_statement(const Stmt& s);
  void args(const std::vector<Expr*>& list);

  const PrintOptions& options_;
  std::string out_;
  int level_ = 0;
  bool suppress_indent_ = false;  // the next line_start continues the current line
  std::unordered_map<std::string, const Expr*> units_;
};

int precedence_of(const Expr& e) {
  if (const auto* b = dyn_cast<BinaryExpr>(&e)) return binary_op_precedence(b->op);
  if (isa<TernaryExpr>(&e)) return 2;
  if (isa<AssignExpr>(&e)) return 2;
  if (isa<UnaryExpr>(&e)) return 14;
  if (isa<ConvertExpr>(&e)) return 13;  // between unary (14) and `*` (13, left-associative, so its lhs is printed at 13)
  return 15;
}

void GlslPrinter::args(const std::vector<Expr*>& list) {
  out_ += '(';
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (i) out_ += ", ";
    expression(*list[i], 2);
  }
  out_ += ')';
}

void GlslPrinter::expression(const Expr& e, int parent_precedence) {
  bool parens = precedence_of(e) < parent_precedence;
  if (parens) out_ += '(';
  switch (e.kind) {
    case NodeKind::IdentifierExpr: {
      const auto& id = static_cast<const IdentifierExpr&>(e);
      auto unit = options_.annotations ? units_.end() : units_.find(id.name);
      if (unit != units_.end()) {
        out_ += '(';
        expression(*unit->second);
        out_ += ')';
      } else {
        out_ += id.name;
      }
      break;
    }
    case NodeKind::LiteralExpr: out_ += static_cast<const LiteralExpr&>(e).spelling; break;
    case NodeKind::UnaryExpr: {
      const auto& u = static_cast<const UnaryExpr&>(e);
      bool postfix = u.op == UnaryOp::PostInc || u.op == UnaryOp::PostDec;
      if (postfix) {
        expression(*u.operand, 15);
        out_ += unary_op_spelling(u.op);
      } else {
        out_ += unary_op_spelling(u.op);
        std::size_t mark = out_.size();
        expression(*u.operand, 14);
        // `- -x`, not `--x`
        char last = unary_op_spelling(u.op).back();
        if (mark < out_.size() && (last == '+' || last == '-') && out_[mark] == last) out_.insert(mark, " ");
      }
      break;
    }
    case NodeKind::BinaryExpr: {
      const auto& b = static_cast<const BinaryExpr&>(e);
      int p = binary_op_precedence(b.op);
      expression(*b.lhs, p);
      out_ += b.op == BinaryOp::Comma ? ", " : " " + std::string(binary_op_spelling(b.op)) + " ";
      expression(*b.rhs, p + 1);
      break;
    }
    case NodeKind::AssignExpr: {
      const auto& a = static_cast<const AssignExpr&>(e);
      expression(*a.lhs, 14);
      out_ += " " + std::string(assign_op_spelling(a.op)) + " ";
      expression(*a.rhs, 2);
      break;
    }
    case NodeKind::TernaryExpr: {
      const auto& t = static_cast<const TernaryExpr&>(e);
      expression(*t.condition, 3);
      out_ += " ? ";
      expression(*t.then_expr, 1);
      out_ += " : ";
      expression(*t.else_expr, 2);
      break;
    }
    case NodeKind::CallExpr: {
      const auto& c = static_cast<const CallExpr&>(e);
      if (c.constructor_type) {
        type(*c.constructor_type);
      } else if (c.callee_expr) {
        expression(*c.callee_expr, 15);
      } else {
        out_ += c.callee;
      }
      if (c.void_arg) {
        out_ += "(void)";
      } else {
        args(c.args);
      }
      break;
    }
    case NodeKind::IndexExpr: {
      const auto& i = static_cast<const IndexExpr&>(e);
      expression(*i.base, 15);
      out_ += '[';
      expression(*i.index);
      out_ += ']';
      break;
    }
    case NodeKind::MemberExpr: {
      const auto& m = static_cast<const MemberExpr&>(e);
      expression(*m.base, 15);
      out_ += '.';
      out_ += m.member;
      break;
    }
    case NodeKind::MethodCallExpr: {
      const auto& m = static_cast<const MethodCallExpr&>(e);
      expression(*m.base, 15);
      out_ += '.';
      out_ += m.method;
      args(m.args);
      break;
    }
    case NodeKind::ParenExpr:
      out_ += '(';
      expression(*static_cast<const ParenExpr&>(e).inner);
      out_ += ')';
      break;
    case NodeKind::ConvertExpr: {
      const auto& c = static_cast<const ConvertExpr&>(e);
      expression(*c.operand, 14);
      out_ += " in ";
      dim(*c.target);
      break;
    }
    case NodeKind::InitializerList: {
      const auto& list = static_cast<const InitializerList&>(e);
      out_ += '{';
      for (std::size_t i = 0; i < list.elements.size(); ++i) {
        if (i) out_ += ", ";
        expression(*list.elements[i], 2);
      }
      if (list.trailing_comma) out_ += ',';
      out_ += '}';
      break;
    }
    default: break;
  }
  if (parens) out_ += ')';
}

void GlslPrinter::dim(const Node& n) {
  switch (n.kind) {
    case NodeKind::DimName: out_ += static_cast<const DimName&>(n).name; break;
    case NodeKind::DimOne: out_ += '1'; break;
    case NodeKind::DimBinary: {
      const auto& b = static_cast<const DimBinary&>(n);
      dim(*b.lhs);
      out_ += b.is_division ? " / " : " * ";
      // `a / (b * c)` keeps its DimParen; a hand-built right operand that is
      // itself a product needs one.
      bool parens = isa<DimBinary>(b.rhs);
      if (parens) out_ += '(';
      dim(*b.rhs);
      if (parens) out_ += ')';
      break;
    }
    case NodeKind::DimPower: {
      const auto& p = static_cast<const DimPower&>(n);
      bool parens = isa<DimBinary>(p.base) || isa<DimPower>(p.base);
      if (parens) out_ += '(';
      dim(*p.base);
      if (parens) out_ += ')';
      out_ += '^';
      out_ += std::to_string(p.exponent);
      break;
    }
    case NodeKind::DimParen:
      out_ += '(';
      dim(*static_cast<const DimParen&>(n).inner);
      out_ += ')';
      break;
    case NodeKind::DimUnit: {
      const auto& u = static_cast<const DimUnit&>(n);
      dim(*u.dimension);
      out_ += " in ";
      dim(*u.unit);
      break;
    }
    case NodeKind::TypeSpecifier: type(static_cast<const TypeSpecifier&>(n)); break;
    default: break;
  }
}

void GlslPrinter::annotation(const Annotation& a) {
  out_ += '<';
  for (std::size_t i = 0; i < a.args.size(); ++i) {
    if (i) out_ += ", ";
    dim(*a.args[i]);
  }
  out_ += '>';  // nested annotations print `>>`, which the parser splits
}

void GlslPrinter::type(const TypeSpecifier& t) {
  if (t.form == TypeSpecifier::Form::Struct) {
    out_ += "struct ";
    if (!t.struct_decl->name.empty()) out_ += t.struct_decl->name + " ";
    members(t.struct_decl->members);
  } else if (t.form == TypeSpecifier::Form::Annotated && !options_.annotations) {
    out_ += annotated_type_representation(t.name);
  } else {
    out_ += t.name;
    if (t.annotation && options_.annotations) annotation(*t.annotation);
  }
  array_dims(t.array_dims);
}

void GlslPrinter::array_dims(const std::vector<ArrayDim>& dims) {
  for (const ArrayDim& d : dims) {
    out_ += '[';
    if (d.size) expression(*d.size);
    out_ += ']';
  }
}

void GlslPrinter::qualifier(const Qualifier& q) {
  if (q.kind == QualifierKind::Spirv) {  // GL_EXT_spirv_intrinsics: as written (canonical spacing)
    out_ += q.spirv_text;
    return;
  }
  out_ += q.word;
  if (q.kind == QualifierKind::Layout) {
    out_ += '(';
    for (std::size_t i = 0; i < q.layout_ids.size(); ++i) {
      if (i) out_ += ", ";
      out_ += q.layout_ids[i].name;
      if (q.layout_ids[i].value) {
        out_ += " = ";
        expression(*q.layout_ids[i].value, 2);
      }
    }
    out_ += ')';
  } else if (q.has_type_list) {
    out_ += '(';
    for (std::size_t i = 0; i < q.type_names.size(); ++i) {
      if (i) out_ += ", ";
      out_ += q.type_names[i];
    }
    out_ += ')';
  }
}

void GlslPrinter::qualifiers(const TypeQualifiers& q) {
  for (const Qualifier& one : q.list) {
    qualifier(one);
    out_ += ' ';
  }
}

void GlslPrinter::members(const std::vector<VariableDecl*>& list) {
  out_ += "{\n";
  ++level_;
  for (const VariableDecl* m : list) {
    line_start();
    variable_decl_inline(*m);
    out_ += ";\n";
  }
  --level_;
  line_start();
  out_ += '}';
}

void GlslPrinter::variable_decl_inline(const VariableDecl& v) {
  qualifiers(v.qualifiers);
  type(*v.type);
  for (std::size_t i = 0; i < v.declarators.size(); ++i) {
    const Declarator& d = v.declarators[i];
    out_ += i ? ", " : " ";
    out_ += d.name;
    array_dims(d.array_dims);
    if (d.initializer) {
      out_ += " = ";
      expression(*d.initializer, 2);
    }
  }
}

void GlslPrinter::declaration(const Decl& d, bool top_level) {
  if (top_level) line_start();
  switch (d.kind) {
    case NodeKind::VariableDecl:
      variable_decl_inline(static_cast<const VariableDecl&>(d));
      out_ += ';';
      break;
    case NodeKind::QualifierDecl: {
      const auto& q = static_cast<const QualifierDecl&>(d);
      qualifiers(q.qualifiers);
      for (std::size_t i = 0; i < q.names.size(); ++i) {
        if (i) out_ += ", ";
        out_ += q.names[i];
      }
      if (!q.names.empty() || out_.back() != ' ') out_ += ';';
      else out_.back() = ';';
      break;
    }
    case NodeKind::FunctionDecl: {
      const auto& f = static_cast<const FunctionDecl&>(d);
      if (!f.template_params.empty() && options_.annotations) {
        out_ += "template<";
        for (std::size_t i = 0; i < f.template_params.size(); ++i) {
          if (i) out_ += ", ";
          out_ += f.template_params[i].kind == TemplateParamKind::Dimension ? "dimension " : "space ";
          out_ += f.template_params[i].name;
        }
        out_ += ">\n";
        line_start();
      }
      qualifiers(f.qualifiers);
      type(*f.return_type);
      out_ += ' ' + f.name + '(';
      if (f.void_param) out_ += "void";
      for (std::size_t i = 0; i < f.params.size(); ++i) {
        const ParamDecl& p = *f.params[i];
        if (i) out_ += ", ";
        qualifiers(p.qualifiers);
        type(*p.type);
        if (!p.name.empty()) out_ += ' ' + p.name;
        array_dims(p.array_dims);
      }
      out_ += ')';
      if (f.body) {
        out_ += ' ';
        statement_inline(*f.body);
      } else {
        out_ += ';';
      }
      break;
    }
    case NodeKind::InterfaceBlockDecl: {
      const auto& b = static_cast<const InterfaceBlockDecl&>(d);
      qualifiers(b.qualifiers);
      out_ += b.block_name + ' ';
      members(b.members);
      if (!b.instance_name.empty()) out_ += ' ' + b.instance_name;
      array_dims(b.instance_array_dims);
      out_ += ';';
      break;
    }
    case NodeKind::PrecisionDecl: {
      const auto& p = static_cast<const PrecisionDecl&>(d);
      out_ += "precision " + p.precision + ' ';
      type(*p.type);
      out_ += ';';
      break;
    }
    case NodeKind::DimensionDecl: {
      if (!options_.annotations) return;
      const auto& dd = static_cast<const DimensionDecl&>(d);
      out_ += "dimension " + dd.name;
      if (dd.ratio) out_ += " : ratio";
      if (dd.definition) {
        out_ += " = ";
        dim(*dd.definition);
      }
      out_ += ';';
      break;
    }
    case NodeKind::UnitDecl: {
      if (!options_.annotations) return;
      const auto& u = static_cast<const UnitDecl&>(d);
      out_ += "unit " + u.name + " : ";
      dim(*u.dimension);
      out_ += " = ";
      expression(*u.scale, 2);
      out_ += ';';
      break;
    }
    case NodeKind::SpaceDecl:
      if (!options_.annotations) return;
      out_ += "space " + static_cast<const SpaceDecl&>(d).name + (static_cast<const SpaceDecl&>(d).eye ? " : eye" : "") +
              (static_cast<const SpaceDecl&>(d).frame ? " : frame" : "") + ';';
      break;
    case NodeKind::EmptyDecl: out_ += ';'; break;
    default: break;
  }
  if (top_level) out_ += '\n';
}

void GlslPrinter::sub_statement(const Stmt& s) {
  if (isa<CompoundStmt>(&s)) {
    out_ += ' ';
    statement_inline(s);
    out_ += '\n';
  } else {
    out_ += '\n';
    ++level_;
    statement(s);
    --level_;
  }
}

void GlslPrinter::statement(const Stmt& s) {
  bool label = isa<CaseLabel>(&s) || isa<DefaultLabel>(&s);
  if (label) --level_;
  line_start();
  if (label) ++level_;
  if (!s.attributes.empty()) {
    out_ += "[[";
    for (std::size_t i = 0; i < s.attributes.size(); ++i) {
      if (i) out_ += ", ";
      out_ += s.attributes[i].name;
      if (s.attributes[i].argument) {
        out_ += '(';
        expression(*s.attributes[i].argument, 2);
        out_ += ')';
      }
    }
    out_ += "]] ";
  }
  switch (s.kind) {
    case NodeKind::IfStmt: {
      const auto& i = static_cast<const IfStmt&>(s);
      out_ += "if (";
      expression(*i.condition);
      out_ += ')';
      // An else must stay with this if, not bind to an inner else-less one.
      const auto* inner_if = dyn_cast<IfStmt>(i.then_stmt);
      bool brace = i.else_stmt && inner_if && !inner_if->else_stmt;
      if (brace) {
        out_ += " {\n";
        ++level_;
        statement(*i.then_stmt);
        --level_;
        line_start();
        out_ += "}\n";
      } else {
        sub_statement(*i.then_stmt);
      }
      if (i.else_stmt) {
        line_start();
        out_ += "else";
        if (isa<IfStmt>(i.else_stmt)) {
          out_ += ' ';
          suppress_indent_ = true;  // `else if` on one line
          statement(*i.else_stmt);
        } else {
          sub_statement(*i.else_stmt);
        }
      }
      return;
    }
    case NodeKind::WhileStmt: {
      const auto& w = static_cast<const WhileStmt&>(s);
      out_ += "while (";
      if (w.condition.decl) variable_decl_inline(*w.condition.decl);
      else expression(*w.condition.expr);
      out_ += ')';
      sub_statement(*w.body);
      return;
    }
    case NodeKind::ForStmt: {
      const auto& f = static_cast<const ForStmt&>(s);
      out_ += "for (";
      statement_inline(*f.init);
      if (f.condition.decl) {
        out_ += ' ';
        variable_decl_inline(*f.condition.decl);
      } else if (f.condition.expr) {
        out_ += ' ';
        expression(*f.condition.expr);
      }
      out_ += ';';
      if (f.increment) {
        out_ += ' ';
        expression(*f.increment);
      }
      out_ += ')';
      sub_statement(*f.body);
      return;
    }
    case NodeKind::DoStmt: {
      const auto& d = static_cast<const DoStmt&>(s);
      out_ += "do";
      sub_statement(*d.body);
      line_start();
      out_ += "while (";
      expression(*d.condition);
      out_ += ");\n";
      return;
    }
    default:
      statement_inline(s);
      out_ += '\n';
      return;
  }
}

void GlslPrinter::statement_inline(const Stmt& s) {
  switch (s.kind) {
    case NodeKind::CompoundStmt: {
      out_ += "{\n";
      ++level_;
      for (const Stmt* child : static_cast<const CompoundStmt&>(s).statements) statement(*child);
      --level_;
      line_start();
      out_ += '}';
      break;
    }
    case NodeKind::DeclStmt: declaration(*static_cast<const DeclStmt&>(s).decl, false); break;
    case NodeKind::ExprStmt:
      expression(*static_cast<const ExprStmt&>(s).expr);
      out_ += ';';
      break;
    case NodeKind::EmptyStmt: out_ += ';'; break;
    case NodeKind::SwitchStmt: {
      const auto& sw = static_cast<const SwitchStmt&>(s);
      out_ += "switch (";
      expression(*sw.selector);
      out_ += ") {\n";
      level_ += 2;  // case labels print one level out, their statements one in
      for (const Stmt* child : sw.body->statements) statement(*child);
      level_ -= 2;
      line_start();
      out_ += '}';
      break;
    }
    case NodeKind::CaseLabel:
      out_ += "case ";
      expression(*static_cast<const CaseLabel&>(s).value);
      out_ += ':';
      break;
    case NodeKind::DefaultLabel: out_ += "default:"; break;
    case NodeKind::BreakStmt: out_ += "break;"; break;
    case NodeKind::ContinueStmt: out_ += "continue;"; break;
    case NodeKind::DiscardStmt: out_ += "discard;"; break;
    case NodeKind::DemoteStmt: out_ += "demote;"; break;
    case NodeKind::ReturnStmt: {
      const auto& r = static_cast<const ReturnStmt&>(s);
      out_ += "return";
      if (r.value) {
        out_ += ' ';
        expression(*r.value);
      }
      out_ += ';';
      break;
    }
    default: {
      // Loops and if statements: print them at the current position.
      suppress_indent_ = true;
      statement(s);
      if (!out_.empty() && out_.back() == '\n') out_.pop_back();
      break;
    }
  }
}

}  // namespace

std::string print_glsl(const TranslationUnit& unit, const PrintOptions& options) {
  return GlslPrinter(options).print_unit(unit);
}

std::string print_expression(const Expr& expr) {
  PrintOptions options;
  GlslPrinter printer(options);
  printer.expression(expr);
  return printer.take();
}

std::string print_qualifier(const Qualifier& qualifier) {
  PrintOptions options;
  GlslPrinter printer(options);
  printer.qualifier(qualifier);
  return printer.take();
}

std::string print_type(const TypeSpecifier& type, bool annotations) {
  PrintOptions options;
  options.annotations = annotations;
  GlslPrinter printer(options);
  printer.type(type);
  return printer.take();
}

}  // namespace safegi
