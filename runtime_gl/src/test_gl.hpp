#pragma once
// GL test helpers: one context per test suite (OSMesa unless
// SAFEGI_GL_PLATFORM says otherwise), the example program, and stand-ins for
// the typed library's types.
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>

#include "safegi/runtime_gl/context.hpp"
#include "safegi/runtime_gl/program.hpp"
#include "test_support.hpp"

namespace safegi::gl::testing {

inline ContextOptions test_context_options() {
  const char* requested = std::getenv("SAFEGI_GL_PLATFORM");
  return ContextOptions{requested && *requested ? platform_from_environment() : Platform::osmesa};
}

class GlTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { context_ = std::make_unique<Context>(test_context_options()); }
  static void TearDownTestSuite() { context_.reset(); }
  void SetUp() override { context_->make_current(); }

  static inline std::unique_ptr<Context> context_;
};

inline ProgramSource example_stage(Stage stage, const std::string& glsl_file, const std::string& table_file) {
  return {stage, read_testdata(glsl_file), parse_symbol_table(read_testdata(table_file), table_file)};
}

inline Program emission_program() {
  return Program({example_stage(Stage::vertex, "emission.vert.glsl", "emission.vert.json"),
                  example_stage(Stage::fragment, "emission.frag.glsl", "emission.frag.json")},
                 "emission");
}

}  // namespace safegi::gl::testing
