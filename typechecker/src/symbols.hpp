#pragma once
// Records CheckResult::symbols while the checker runs (CheckOptions::record_symbols):
// each declaration and use of a name, with its declaration and type. Every
// method returns at once when recording is off, so the checker calls them
// unconditionally and a driver's compilation pays one branch per name.

#include <map>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "safegi/typechecker/checker.hpp"

namespace safegi::detail {

class SymbolRecorder {
 public:
  // `out` null: recording is off.
  SymbolRecorder(std::vector<SymbolOccurrence>* out, const DimensionRegistry& registry) : out_(out), registry_(&registry) {}

  // After the annotation declarations are in the registry (Checker::run):
  // records each dimension, unit and space declaration, and resolves the uses
  // recorded while they were declared (`radiance = irradiance / …`).
  void annotation_declarations(const ast::TranslationUnit& unit);
  void use_dimension(const std::string& name, SourceRange range, const Dimension& value);
  void use_unit(const std::string& name, SourceRange range, const Dimension& value);
  void use_space(const std::string& name, SourceRange range);

  // The template parameters in scope while `f` is declared and checked (nullptr: none).
  void enter_function(const ast::FunctionDecl* f);
  void use_dimension_parameter(const std::string& name, SourceRange range);
  void use_space_parameter(const std::string& name, SourceRange range);

  void declare_variable(const std::string& name, SourceRange range, const Type& type);
  void use_variable(const std::string& name, SourceRange range, SourceRange declaration, const Type& type, bool builtin);
  // `params`: the resolved parameter types, in order.
  void declare_function(const ast::FunctionDecl& f, const Type& result, const std::vector<Type>& params);
  void use_function(const std::string& name, SourceRange range, const ast::FunctionDecl* declaration, const Type& result);
  // The result of the call whose function was recorded last, once unification knows it.
  void call_result(const Type& result);
  void use_builtin_function(const std::string& name, SourceRange range, const std::string& signature, const Type& result);
  void declare_structure(const StructInfo* info, const ast::StructDecl& decl);
  void use_structure(const StructInfo* info, SourceRange range);
  // The members of a struct or of a block with an instance name, as `info`'s fields.
  void declare_fields(const StructInfo* info, const std::vector<ast::VariableDecl*>& members);
  void use_field(const StructInfo* info, const std::string& name, SourceRange range, const Type& type);

 private:
  void add(SymbolKind kind, const std::string& name, SourceRange range, SourceRange declaration, bool is_declaration,
           const Type& type, std::string text);
  std::string text_of(const Type& t) const;
  static Type dimension_type(const Dimension& d, const std::string& spelling);

  std::vector<SymbolOccurrence>* out_;
  const DimensionRegistry* registry_;
  std::unordered_map<std::string, SourceRange> annotations_;  // dimension, unit and space names: first declaration
  const ast::FunctionDecl* function_ = nullptr;
  std::vector<std::string> dim_params_, space_params_;
  std::unordered_map<const ast::FunctionDecl*, std::string> signatures_;
  std::unordered_map<const StructInfo*, SourceRange> structures_;
  std::map<std::pair<const StructInfo*, std::string>, SourceRange> fields_;
};

}  // namespace safegi::detail
