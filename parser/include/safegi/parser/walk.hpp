#pragma once
// Pre-order traversal of every node of a syntax tree, type specifiers and
// annotation arguments included. The parser bounds tree height, so recursion
// is safe here.

#include <functional>

#include "ast.hpp"

namespace safegi::ast {

using Visitor = std::function<void(const ast::Node&)>;
void walk(const ast::Node* node, const Visitor& visit);

}  // namespace safegi::ast
