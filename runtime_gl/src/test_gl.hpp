#pragma once
// GL test helpers: one context per test suite (OSMesa unless
// SAFEGI_GL_PLATFORM says otherwise), the example program, and stand-ins for
// the typed library's types.
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <string>

#include "safegi/runtime_gl/context.hpp"
#include "safegi/symbol_table/error.hpp"
#include "safegi/runtime_gl/program.hpp"
#include "read_testdata.hpp"

namespace safegi::gl::testing {

// The GL version the test contexts ask for: 4.5 (direct state access paths),
// or 3.3 (bind-and-restore paths) when SAFEGI_GL_TEST_VERSION=33.
inline ContextOptions test_context_options() {
  const char* requested = std::getenv("SAFEGI_GL_PLATFORM");
  const char* version = std::getenv("SAFEGI_GL_TEST_VERSION");
  const bool core33 = version && std::string(version) == "33";
  return ContextOptions{requested && *requested ? platform_from_environment() : Platform::osmesa, core33 ? 3 : 4,
                        core33 ? 3 : 5};
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

// A test with the example program linked; error_of() runs a lookup and gives
// the BindingError's text ("no error" when it succeeds).
class ExampleProgramTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    program_ = std::make_unique<Program>(emission_program());
  }
  template <class Lookup>
  std::string error_of(Lookup lookup) {
    try {
      lookup(*program_);
    } catch (const BindingError& error) {
      return error.what();
    }
    return "no error";
  }
  std::unique_ptr<Program> program_;
};

}  // namespace safegi::gl::testing
