#pragma once
// The test shaders: safeglslc checked them and wrote their SPIR-V and symbol
// tables at build time (SAFEGI_VK_SHADER_DIR).
#include <string>

#include "safegi/runtime_vk/pipeline.hpp"

namespace safegi::vk::testing {

inline ComputeShader test_shader(const std::string& stem) {
  const std::string base = std::string(SAFEGI_VK_SHADER_DIR) + "/" + stem;
  return {read_spirv_file(base + ".spv"), read_symbol_table_file(base + ".json"), stem};
}

}  // namespace safegi::vk::testing
