#pragma once
// Vulkan test helpers: one context per test suite (lavapipe unless
// SAFEGI_VK_DEVICE says otherwise; validation as SAFEGI_VK_VALIDATION says,
// which ctest sets to fatal) and error_of().
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "safegi/runtime_vk/runtime_vk.hpp"
#include "test_shaders.hpp"

namespace safegi::vk::testing {

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
