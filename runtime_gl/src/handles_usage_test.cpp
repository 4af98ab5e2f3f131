// A host written against the header safegi-gl-handles generated at build time
// from testdata/emission.program.json: its handles have the shader's types.
#include <gtest/gtest.h>

#include "emission_handles.hpp"
#include "safegi/symbol_table/error.hpp"
#include "test_gl.hpp"

namespace safegi::gl {
namespace {

using Handles = shaders::emission::Handles;

class HandlesUsageTest : public testing::ExampleProgramTest {};

TEST_F(HandlesUsageTest, TheGeneratedHandlesAreTheCheckedLookups) {
  const Handles handles(*program_);
  EXPECT_EQ(handles.Le.location, program_->uniform<shaders::emission::Le_type>("Le").location);
  EXPECT_EQ(handles.color.location, 0);
  EXPECT_EQ(handles.tint.size, 2);
  program_->set(handles.Le, from_raw<shaders::emission::Le_type>(glm::vec3(1, 2, 3)));
  program_->set(handles.exposure, 2.0f);
}

TEST_F(HandlesUsageTest, AProgramFromOtherSourcesIsRefused) {
  try {
    program_->expect_source_hash(Stage::fragment, "fnv1a64:0000000000000000");
    FAIL();
  } catch (const BindingError& error) {
    EXPECT_STREQ(error.what(),
                 "emission: error: the handles were generated from emission.sgl.frag with source hash "
                 "fnv1a64:0000000000000000, but the program was built from source hash fnv1a64:2c14201eeb22e19d; "
                 "regenerate the header");
  }
}

// The point of the header: the wrong dimension does not compile.
template <class Handle, class Value>
concept settable = requires(const Program& program, Handle handle, Value value) { program.set(handle, value); };
static_assert(settable<decltype(Handles::Le), spectrum<dim::radiance>>);
static_assert(!settable<decltype(Handles::Le), spectrum<dim::irradiance>>);
static_assert(!settable<decltype(Handles::exposure), quantity<dim::length>>);

}  // namespace
}  // namespace safegi::gl
