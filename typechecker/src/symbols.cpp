#include "symbols.hpp"

namespace safegi {

const char* symbol_kind_name(SymbolKind kind) {
  switch (kind) {
    case SymbolKind::variable: return "variable";
    case SymbolKind::field: return "field";
    case SymbolKind::function: return "function";
    case SymbolKind::structure: return "struct";
    case SymbolKind::builtin_variable: return "built-in variable";
    case SymbolKind::builtin_function: return "built-in function";
    case SymbolKind::dimension: return "dimension";
    case SymbolKind::unit: return "unit";
    case SymbolKind::space: return "space";
    case SymbolKind::dimension_parameter: return "dimension parameter";
    case SymbolKind::space_parameter: return "space parameter";
  }
  return "symbol";
}

namespace detail {

void SymbolRecorder::add(SymbolKind kind, const std::string& name, SourceRange range, SourceRange declaration,
                         bool is_declaration, const Type& type, std::string text) {
  out_->push_back({kind, name, range, declaration, is_declaration, type, std::move(text)});
}

std::string SymbolRecorder::text_of(const Type& t) const {
  return type_name(t, *registry_, function_ ? &dim_params_ : nullptr, function_ ? &space_params_ : nullptr);
}

Type SymbolRecorder::dimension_type(const Dimension& d, const std::string& spelling) {
  Type t = Type::scalar_of(Scalar::float_);
  t.dim = DimSlot::known(d, spelling);
  return t;
}

// ------------------------------------------------------------- annotations

void SymbolRecorder::annotation_declarations(const ast::TranslationUnit& unit) {
  if (!out_) return;
  for (const ast::Decl* d : unit.decls) {
    SymbolKind kind = SymbolKind::space;
    const std::string* name = nullptr;
    SourceRange range;
    if (const auto* dim = ast::dyn_cast<ast::DimensionDecl>(d)) {
      kind = SymbolKind::dimension;
      name = &dim->name;
      range = dim->name_range;
    } else if (const auto* u = ast::dyn_cast<ast::UnitDecl>(d)) {
      kind = SymbolKind::unit;
      name = &u->name;
      range = u->name_range;
    } else if (const auto* s = ast::dyn_cast<ast::SpaceDecl>(d)) {
      name = &s->name;
      range = s->name_range;
    } else {
      continue;
    }
    // Declared again identically (a header included twice): the first declaration is the definition.
    const SourceRange first = annotations_.emplace(*name, range).first->second;
    Type type;
    std::string text;
    if (kind == SymbolKind::dimension) {
      if (std::optional<Dimension> value = registry_->find_dimension(*name)) type = dimension_type(*value, *name);
    } else if (kind == SymbolKind::unit) {
      if (const Unit* u = registry_->find_unit(*name)) type = dimension_type(u->dimension, {});
    }
    if (!type.is_error()) text = text_of(type);
    add(kind, *name, range, first, true, type, std::move(text));
  }
  for (SymbolOccurrence& o : *out_) {
    const bool annotation = o.kind == SymbolKind::dimension || o.kind == SymbolKind::unit || o.kind == SymbolKind::space;
    if (annotation && !o.declaration.valid())
      if (auto it = annotations_.find(o.name); it != annotations_.end()) o.declaration = it->second;
  }
}

void SymbolRecorder::use_dimension(const std::string& name, SourceRange range, const Dimension& value) {
  if (!out_) return;
  auto it = annotations_.find(name);
  const Type type = dimension_type(value, name);
  add(SymbolKind::dimension, name, range, it == annotations_.end() ? SourceRange{} : it->second, false, type, text_of(type));
}

void SymbolRecorder::use_unit(const std::string& name, SourceRange range, const Dimension& value) {
  if (!out_) return;
  auto it = annotations_.find(name);
  const Type type = dimension_type(value, {});
  add(SymbolKind::unit, name, range, it == annotations_.end() ? SourceRange{} : it->second, false, type, text_of(type));
}

void SymbolRecorder::use_space(const std::string& name, SourceRange range) {
  if (!out_) return;
  auto it = annotations_.find(name);
  add(SymbolKind::space, name, range, it == annotations_.end() ? SourceRange{} : it->second, false, Type::error(), {});
}

// ----------------------------------------------------- template parameters

void SymbolRecorder::enter_function(const ast::FunctionDecl* f) {
  if (!out_) return;
  function_ = f;
  dim_params_.clear();
  space_params_.clear();
  if (!f) return;
  for (const ast::TemplateParam& p : f->template_params) {
    const bool dimension = p.kind == ast::TemplateParamKind::Dimension;
    (dimension ? dim_params_ : space_params_).push_back(p.name);
    add(dimension ? SymbolKind::dimension_parameter : SymbolKind::space_parameter, p.name, p.name_range, p.name_range,
        true, Type::error(), {});
  }
}

void SymbolRecorder::use_dimension_parameter(const std::string& name, SourceRange range) {
  if (!out_ || !function_) return;
  for (const ast::TemplateParam& p : function_->template_params)
    if (p.kind == ast::TemplateParamKind::Dimension && p.name == name)
      return add(SymbolKind::dimension_parameter, name, range, p.name_range, false, Type::error(), {});
}

void SymbolRecorder::use_space_parameter(const std::string& name, SourceRange range) {
  if (!out_ || !function_) return;
  for (const ast::TemplateParam& p : function_->template_params)
    if (p.kind == ast::TemplateParamKind::Space && p.name == name)
      return add(SymbolKind::space_parameter, name, range, p.name_range, false, Type::error(), {});
}

// ---------------------------------------------------- variables, functions

void SymbolRecorder::declare_variable(const std::string& name, SourceRange range, const Type& type) {
  if (!out_ || name.empty()) return;
  add(SymbolKind::variable, name, range, range, true, type, text_of(type));
}

void SymbolRecorder::use_variable(const std::string& name, SourceRange range, SourceRange declaration, const Type& type,
                                  bool builtin) {
  if (!out_) return;
  add(builtin ? SymbolKind::builtin_variable : SymbolKind::variable, name, range, builtin ? SourceRange{} : declaration,
      false, type, text_of(type));
}

void SymbolRecorder::declare_function(const ast::FunctionDecl& f, const Type& result, const std::vector<Type>& params) {
  if (!out_) return;
  std::string text;
  if (!f.template_params.empty()) {
    text = "template<";
    for (std::size_t i = 0; i < f.template_params.size(); ++i) {
      const ast::TemplateParam& p = f.template_params[i];
      text += std::string(i ? ", " : "") + (p.kind == ast::TemplateParamKind::Dimension ? "dimension " : "space ") + p.name;
    }
    text += "> ";
  }
  text += text_of(result) + " " + f.name + "(";
  for (std::size_t i = 0; i < params.size() && i < f.params.size(); ++i) {
    text += (i ? ", " : "") + text_of(params[i]);
    if (!f.params[i]->name.empty()) text += " " + f.params[i]->name;
  }
  text += ")";
  signatures_[&f] = text;
  add(SymbolKind::function, f.name, f.name_range, f.name_range, true, result, std::move(text));
}

void SymbolRecorder::use_function(const std::string& name, SourceRange range, const ast::FunctionDecl* declaration,
                                  const Type& result) {
  if (!out_) return;
  auto it = signatures_.find(declaration);
  add(SymbolKind::function, name, range, declaration ? declaration->name_range : SourceRange{}, false, result,
      it == signatures_.end() ? text_of(result) : it->second);
}

void SymbolRecorder::call_result(const Type& result) {
  if (!out_) return;
  for (auto it = out_->rbegin(); it != out_->rend(); ++it)
    if (it->kind == SymbolKind::function && !it->is_declaration) {
      it->type = result;
      return;
    }
}

void SymbolRecorder::use_builtin_function(const std::string& name, SourceRange range, const std::string& signature,
                                          const Type& result) {
  if (!out_) return;
  add(SymbolKind::builtin_function, name, range, {}, false, result, signature.empty() ? "" : name + ": " + signature);
}

// --------------------------------------------------------- structs, fields

void SymbolRecorder::declare_structure(const StructInfo* info, const ast::StructDecl& decl) {
  if (!out_ || decl.name.empty()) return;
  structures_[info] = decl.name_range;
  Type t;
  t.shape = Shape::structure;
  t.structure = info;
  add(SymbolKind::structure, decl.name, decl.name_range, decl.name_range, true, t, "struct " + decl.name);
}

void SymbolRecorder::use_structure(const StructInfo* info, SourceRange range) {
  if (!out_ || !info) return;
  auto it = structures_.find(info);
  Type t;
  t.shape = Shape::structure;
  t.structure = info;
  add(SymbolKind::structure, info->name, range, it == structures_.end() ? SourceRange{} : it->second, false, t,
      "struct " + info->name);
}

void SymbolRecorder::declare_fields(const StructInfo* info, const std::vector<ast::VariableDecl*>& members) {
  if (!out_ || !info) return;
  for (const ast::VariableDecl* member : members)
    for (const ast::Declarator& d : member->declarators) {
      const StructField* field = nullptr;
      for (const StructField& f : info->fields)
        if (f.name == d.name) field = &f;
      if (!field) continue;
      fields_.emplace(std::pair{info, d.name}, d.name_range);
      add(SymbolKind::field, d.name, d.name_range, d.name_range, true, field->type, text_of(field->type));
    }
}

void SymbolRecorder::use_field(const StructInfo* info, const std::string& name, SourceRange range, const Type& type) {
  if (!out_) return;
  auto it = fields_.find({info, name});
  add(SymbolKind::field, name, range, it == fields_.end() ? SourceRange{} : it->second, false, type, text_of(type));
}

}  // namespace detail
}  // namespace safegi
