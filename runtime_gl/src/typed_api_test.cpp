// The typed API against the example program: lookups that succeed, lookups that
// fail with exact messages, values that do not compile, and one frame drawn
// into a typed framebuffer and read back.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "safegi/symbol_table/error.hpp"
#include "safegi/runtime_gl/gl.hpp"
#include "safegi/runtime_gl/program.hpp"
#include "safegi/runtime_gl/resources.hpp"
#include "emission_scene.hpp"
#include "test_gl.hpp"
#include "test_types.hpp"

namespace safegi::gl {
namespace {

using testing::camera_from_world;
using testing::irradiance_rgb;
using testing::unitless_rgb;
using testing::ndc_point;
using testing::radiance_rgb;
using testing::world_point;

class TypedApiTest : public testing::ExampleProgramTest {};

TEST_F(TypedApiTest, LookupsOfTheDeclaredTypesSucceed) {
  EXPECT_GE(program_->uniform<radiance_rgb>("Le").location, 0);
  EXPECT_GE(program_->uniform<float>("exposure").location, 0);
  EXPECT_GE(program_->attribute<ndc_point>("position").location, 0);
  EXPECT_GE(program_->attribute<radiance_rgb>("vertexLe").location, 0);
  EXPECT_EQ(program_->output<radiance_rgb>("color").location, 0);
  EXPECT_GE(program_->sampler<radiance_rgb>("environment").location, 0);
}

TEST_F(TypedApiTest, AVariableTheDriverOptimizedAwayIsANoOpHandle) {
  // cameraFromWorld is declared (so the lookup is checked) but never used.
  EXPECT_EQ(program_->uniform<camera_from_world>("cameraFromWorld").location, -1);
  program_->set(program_->uniform<camera_from_world>("cameraFromWorld"), camera_from_world{});
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(TypedApiTest, AWrongDimensionNamesTheDeclarationAndBothTypes) {
  EXPECT_EQ(error_of([](const Program& p) { p.uniform<irradiance_rgb>("Le"); }),
            "emission.sgl.frag:6:28: error: uniform 'Le' is declared with type spectrum<radiance> but the host "
            "uses spectrum<irradiance> (dimension differs)");
}

TEST_F(TypedApiTest, AWrongSpaceOrKindIsNamedToo) {
  EXPECT_EQ(error_of([](const Program& p) { p.attribute<world_point>("position"); }),
            "emission.sgl.vert:5:15: error: vertex attribute 'position' is declared with type point<ndc> but the "
            "host uses point<world> (space differs)");
  EXPECT_EQ(error_of([](const Program& p) { p.uniform<glm::vec3>("Le"); }),
            "emission.sgl.frag:6:28: error: uniform 'Le' is declared with type spectrum<radiance> but the host "
            "uses vec3 (kind and dimension differ)");
  EXPECT_EQ(error_of([](const Program& p) { p.uniform<glm::mat3>("cameraFromWorld"); }),
            "emission.sgl.frag:10:28: error: uniform 'cameraFromWorld' is declared with type map<world, camera> but "
            "the host uses mat3 (kind, GLSL type and space differ)");
}

TEST_F(TypedApiTest, AMissingNameListsWhereItWasLookedFor) {
  EXPECT_EQ(error_of([](const Program& p) { p.uniform<radiance_rgb>("Lx"); }),
            "emission: error: no uniform named 'Lx' in emission.sgl.vert, emission.sgl.frag");
  EXPECT_EQ(error_of([](const Program& p) { p.attribute<radiance_rgb>("Le"); }),
            "emission: error: no vertex attribute named 'Le' in emission.sgl.vert");
  EXPECT_EQ(error_of([](const Program& p) { p.output<radiance_rgb>("Lv"); }),
            "emission: error: no fragment output named 'Lv' in emission.sgl.frag");
}

TEST_F(TypedApiTest, ArraysSamplersAndBlocksNeedTheirOwnLookups) {
  EXPECT_EQ(error_of([](const Program& p) { p.uniform<glm::vec3>("tint"); }),
            "emission.sgl.frag:8:21: error: uniform 'tint' is an array of 2; look it up with uniform_array<T>");
  EXPECT_EQ(error_of([](const Program& p) { p.uniform_array<float>("exposure"); }),
            "emission.sgl.frag:7:15: error: uniform array 'exposure' is not an array; look it up with uniform<T>");
  EXPECT_EQ(error_of([](const Program& p) { p.sampler<irradiance_rgb>("environment"); }),
            "emission.sgl.frag:9:39: error: sampler 'environment' is declared with texels type spectrum<radiance> "
            "but the host uses spectrum<irradiance> (dimension differs)");
  EXPECT_EQ(error_of([](const Program& p) { p.sampler<radiance_rgb>("Le"); }),
            "emission.sgl.frag:6:28: error: sampler 'Le' is declared as spectrum<radiance>, not as a sampler");
  EXPECT_EQ(error_of([](const Program& p) { p.uniform<float>("Camera.focalLength"); }),
            "emission.sgl.frag:11:81: error: uniform 'Camera.focalLength' is a member of uniform block 'Camera'; "
            "set it through a uniform buffer");
}

TEST_F(TypedApiTest, TheUncheckedModeOnlyAsksTheDriver) {
  const int checked = program_->uniform<radiance_rgb>("Le").location;
  EXPECT_EQ((program_->uniform<irradiance_rgb, unchecked_mode>("Le").location), checked);
  EXPECT_EQ((program_->uniform<radiance_rgb, unchecked_mode>("Lx").location), -1);
}

// Setting a value of another type than the handle's does not compile.
template <class Handle, class Value>
concept settable = requires(const Program& program, Handle handle, Value value) { program.set(handle, value); };
static_assert(settable<uniform_id<radiance_rgb>, radiance_rgb>);
static_assert(!settable<uniform_id<radiance_rgb>, irradiance_rgb>);
static_assert(!settable<uniform_id<radiance_rgb>, glm::vec3>);
static_assert(!settable<uniform_id<float>, double>);
static_assert(settable<uniform_array_id<unitless_rgb>, std::array<unitless_rgb, 2>>);
static_assert(settable<uniform_array_id<unitless_rgb>, std::vector<unitless_rgb>>);
static_assert(!settable<uniform_array_id<unitless_rgb>, std::array<radiance_rgb, 2>>);
template <class Attribute, class Buffer>
concept bindable = requires(vertex_array array, Attribute attribute, const Buffer& buffer) {
  array.bind(attribute, buffer);
};
static_assert(bindable<attribute_id<ndc_point>, vertex_buffer<ndc_point>>);
static_assert(!bindable<attribute_id<ndc_point>, vertex_buffer<world_point>>);
template <class Output, class Texture>
concept attachable = requires(framebuffer target, Output output, const Texture& texture) {
  target.attach(output, texture);
};
static_assert(attachable<output_id<radiance_rgb>, texture2d<radiance_rgb>>);
static_assert(!attachable<output_id<radiance_rgb>, texture2d<irradiance_rgb>>);
template <class Sampler, class Texture>
concept samplable = requires(const Program& program, Sampler sampler, const Texture& texture) {
  program.bind(sampler, texture, 0);
};
static_assert(samplable<sampler_id<radiance_rgb>, texture2d<radiance_rgb>>);
static_assert(!samplable<sampler_id<radiance_rgb>, texture2d<glm::vec3>>);

TEST_F(TypedApiTest, DrawsAFrameIntoATypedFramebuffer) {
  using Scene = testing::EmissionScene;
  const Program& program = *program_;
  Scene scene(program);
  program.bind(program.sampler<radiance_rgb>("environment"), scene.sky_texture, 3);
  program.set(program.uniform<radiance_rgb>("Le"), Scene::le);
  program.set(program.uniform<float>("exposure"), Scene::exposure);
  program.set(program.uniform_array<unitless_rgb>("tint"), std::span(Scene::tints));

  texture2d<radiance_rgb> image(4, 3);
  framebuffer target(4, 3);
  target.attach(program.output<radiance_rgb>("color"), image);
  target.bind();
  program.use();
  scene.triangle.draw_triangles(0, 3);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));

  const radiance_rgb expected = Scene::expected_pixel(Scene::le);
  EXPECT_EQ(expected, (radiance_rgb{8.0f, 5.5f, 3.625f}));
  for (const radiance_rgb& pixel : image.read_back()) EXPECT_EQ(pixel, expected);
}

TEST_F(TypedApiTest, TooManyValuesForAUniformArrayIsAnError) {
  const std::array<unitless_rgb, 3> three{};
  try {
    program_->set(program_->uniform_array<unitless_rgb>("tint"), std::span<const unitless_rgb>(three));
    FAIL();
  } catch (const BindingError& error) {
    EXPECT_STREQ(error.what(), "emission: error: 3 values for a uniform array of 2");
  }
}

}  // namespace
}  // namespace safegi::gl
