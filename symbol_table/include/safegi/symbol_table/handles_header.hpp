#pragma once
// Beyond the paper: a C++ header of typed handles generated from a symbol
// table, so that a host value of another dimension or space than the shader
// declares fails the C++ build, not shader load. The handles are still looked
// up (and checked) at run time, and the header remembers each stage's source
// hash so a stale header is reported instead of silently trusted.
#include <map>
#include <string>

#include "safegi/symbol_table/symbol_table.hpp"

namespace safegi::gl {

struct HandlesHeaderOptions {
  std::string namespace_name = "shaders";  // C++ namespace of the generated struct
  std::string struct_name = "Handles";
  std::string origin;                      // the table's file name, for the banner
  // C++ spelling of base dimensions and spaces beyond the typed library's own
  // (pixel -> "::my::pixel"): a base maps to a dimension type, a space to a tag.
  std::map<std::string, std::string> cpp_names;
  // opengl: handles for a runtime_gl Program. vulkan: handles for a runtime_vk
  // ComputePipeline, and every block's layout (offsets, sizes, strides, sets,
  // bindings) as constants that static_asserts on host structs can use.
  Client api = Client::opengl;
};

// Throws SymbolTableError when a symbol's type has no C++ spelling (or, for
// Vulkan, the table has no Vulkan compute stage).
std::string generate_handles_header(const SymbolTable& table, const HandlesHeaderOptions& options);

}  // namespace safegi::gl
