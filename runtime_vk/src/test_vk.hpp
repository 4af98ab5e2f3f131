#pragma once
// Vulkan test helpers: one context per test suite (lavapipe unless
// SAFEGI_VK_DEVICE says otherwise; validation as SAFEGI_VK_VALIDATION says,
// which ctest sets to fatal), and the test shaders safeglslc compiled at
// build time (SAFEGI_VK_SHADER_DIR).
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "safegi/runtime_vk/runtime_vk.hpp"

namespace safegi::vk::testing {

inline ComputeShader test_shader(const std::string& stem) {
  const std::string base = std::string(SAFEGI_VK_SHADER_DIR) + "/" + stem;
  return {read_spirv_file(base + ".spv"), read_symbol_table_file(base + ".json"), stem};
}

class VulkanTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { context_ = std::make_unique<Context>(); }
  static void TearDownTestSuite() { context_.reset(); }
  // Validation::record would keep messages here; with fatal (ctest) the first
  // one has already ended the process.
  void TearDown() override { EXPECT_TRUE(context_->take_validation_messages().empty()); }
  static Context& context() { return *context_; }

  static inline std::unique_ptr<Context> context_;
};

// The text of the Error `action` throws ("no error" when it throws none).
template <class Action>
std::string error_of(Action action) {
  try {
    action();
  } catch (const Error& error) {
    return error.what();
  }
  return "no error";
}

}  // namespace safegi::vk::testing
