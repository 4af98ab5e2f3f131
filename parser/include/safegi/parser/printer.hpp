#pragma once
// Writing a syntax tree back out: as GLSL (with or without the SafeGI
// annotations) and as an indented dump for golden tests and round-trip checks.

#include <string>

#include <safegi/parser/ast.hpp>

namespace safegi {

struct PrintOptions {
  // false: erase annotations the simple way — annotated types print as their
  // GLSL representation, annotation declarations and template headers are
  // dropped, unit names become their scale. (The elider does the
  // line-preserving erasure; this is for tests and tools.)
  bool annotations = true;
  std::string indent = "    ";
  // Printed first, e.g. "#version 450\n" and #extension lines, which the
  // preprocessor consumed and the tree does not hold.
  std::string preamble;
};

std::string print_glsl(const ast::TranslationUnit& unit, const PrintOptions& options = {});
std::string print_expression(const ast::Expr& expr);
std::string print_type(const ast::TypeSpecifier& type, bool annotations = true);
std::string print_qualifier(const ast::Qualifier& qualifier);  // "layout(location = 0)", "flat"

struct DumpOptions {
  bool ranges = false;  // append `@line:col-line:col` to each node
};

// One node per line, children indented by two spaces. Parse -> print -> parse
// gives the same dump (without ranges): that is the round-trip test.
std::string dump_ast(const ast::Node& node, const DumpOptions& options = {});

}  // namespace safegi
