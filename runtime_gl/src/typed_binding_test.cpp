// The typed library's own types against the example program. Built twice: with
// SafeGI::runtime_gl (checked: mismatches throw with both types in words) and
// with SafeGI::runtime_gl_unchecked (the same source; the checks vanish).
#include <gtest/gtest.h>

#include <array>
#include <safegi/typed.hpp>
#include <vector>

#include "safegi/symbol_table/error.hpp"
#include "safegi/runtime_gl/gl.hpp"
#include "safegi/runtime_gl/runtime_gl.hpp"
#include "test_gl.hpp"
#include "typed_emission_scene.hpp"

namespace safegi::gl {
namespace {

using radiance = spectrum<dim::radiance>;
using irradiance = spectrum<dim::irradiance>;
using ndc_point = point<spaces::ndc>;
using world_point = point<spaces::world>;
using tint = spectrum<dim::dimensionless>;

class TypedBindingTest : public testing::ExampleProgramTest {};

radiance rgb_radiance(float r, float g, float b) { return from_raw<radiance>(glm::vec3(r, g, b)); }

TEST_F(TypedBindingTest, TheDeclaredTypesBind) {
  EXPECT_GE(program_->uniform<radiance>("Le").location, 0);
  EXPECT_GE(program_->uniform<float>("exposure").location, 0);
  EXPECT_GE(program_->uniform_array<tint>("tint").location, 0);
  EXPECT_GE(program_->attribute<ndc_point>("position").location, 0);
  EXPECT_EQ(program_->output<radiance>("color").location, 0);
  EXPECT_GE(program_->sampler<radiance>("environment").location, 0);
  EXPECT_EQ((program_->uniform<map<spaces::world, spaces::camera>>("cameraFromWorld").location), -1);
}

TEST_F(TypedBindingTest, MismatchesThrowInTheCheckedBuildOnly) {
  const std::string radiance_vs_irradiance = error_of([](const Program& p) { p.uniform<irradiance>("Le"); });
  const std::string ndc_vs_world = error_of([](const Program& p) { p.attribute<world_point>("position"); });
  const std::string map_spaces =
      error_of([](const Program& p) { p.uniform<map<spaces::camera, spaces::world>>("cameraFromWorld"); });
  const std::string length_vs_plain =
      error_of([](const Program& p) { p.uniform<quantity<dim::length>>("exposure"); });
  if constexpr (build_mode::checks) {
    EXPECT_EQ(radiance_vs_irradiance,
              "emission.sgl.frag:6:28: error: uniform 'Le' is declared with type spectrum<radiance> but the host "
              "uses spectrum<irradiance> (dimension differs)");
    EXPECT_EQ(ndc_vs_world,
              "emission.sgl.vert:5:15: error: vertex attribute 'position' is declared with type point<ndc> but the "
              "host uses point<world> (space differs)");
    EXPECT_EQ(map_spaces,
              "emission.sgl.frag:10:28: error: uniform 'cameraFromWorld' is declared with type map<world, camera> "
              "but the host uses map<camera, world> (space differs)");
    EXPECT_EQ(length_vs_plain,
              "emission.sgl.frag:7:15: error: uniform 'exposure' is declared with type float but the host uses "
              "float<length> (kind and dimension differ)");
  } else {
    for (const std::string& error : {radiance_vs_irradiance, ndc_vs_world, map_spaces, length_vs_plain})
      EXPECT_EQ(error, "no error");
  }
}

TEST_F(TypedBindingTest, TexturesKeepTheirTexelType) {
  const std::vector<radiance> texels{rgb_radiance(1, 2, 3), rgb_radiance(0.5f, 0.25f, 0.125f),
                                     rgb_radiance(1e-20f, 1e20f, 0), rgb_radiance(7, 8, 9)};
  texture2d<radiance> texture(2, 2, texels);
  const std::vector<radiance> back = texture.read_back();
  ASSERT_EQ(back.size(), texels.size());
  for (std::size_t i = 0; i < texels.size(); ++i) EXPECT_EQ(raw(back[i]), raw(texels[i]));
}

TEST_F(TypedBindingTest, DrawsWithTypedValues) {
  const Program& program = *program_;
  testing::TypedEmissionScene scene(program);
  scene.set_uniforms(program, 1);
  program.set(program.uniform<radiance>("Le"), rgb_radiance(1, 2, 3));

  texture2d<radiance> image(2, 2);
  framebuffer target(2, 2);
  target.attach(program.output<radiance>("color"), image);
  target.bind();
  program.use();
  scene.triangle.draw_triangles(0, 3);
  for (const radiance& pixel : image.read_back()) EXPECT_EQ(raw(pixel), glm::vec3(8.0f, 5.5f, 3.625f));
}

// A host value of another dimension or space than the handle's does not
// compile (checked build); in the unchecked build the types coincide.
template <class Handle, class Value>
concept settable = requires(const Program& program, Handle handle, Value value) { program.set(handle, value); };
static_assert(settable<uniform_id<radiance>, radiance>);
static_assert(settable<uniform_id<radiance>, irradiance> == !build_mode::checks);
template <class Attribute, class Buffer>
concept bindable = requires(vertex_array array, Attribute attribute, const Buffer& buffer) {
  array.bind(attribute, buffer);
};
static_assert(bindable<attribute_id<ndc_point>, vertex_buffer<world_point>> == !build_mode::checks);

}  // namespace
}  // namespace safegi::gl
