// The compute path end to end on the test shaders. Built twice, with
// SafeGI::runtime_vk (checked) and SafeGI::runtime_vk_unchecked: the same
// source, the same results.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "test_types.hpp"
#include "test_vk.hpp"

namespace safegi::vk {
namespace {

using namespace testing;

class ComputeTest : public VulkanTest {};

// scale.sgl.comp: target[i] = (source[i] * factor + tint * weights[1]) * exposure,
// also stored in the image at (i % row_length, i / row_length), for i < count.
TEST_F(ComputeTest, ScalesRadianceByAPushConstantAndWritesAnImage) {
  Specialization specialization;
  specialization.set("gl_WorkGroupSize.x", 4u).set("exposure", 2.0f).set(2u, 4u);  // id 2: row_length
  ComputePipeline pipeline(context(), test_shader("scale"), specialization);

  const std::vector<radiance> input = {
      rgb(1, 2, 3),    rgb(0.5f, 0.25f, 0.125f), rgb(0, 0, 0),      rgb(4, 8, 16), rgb(-1, 1, -1),
      rgb(10, 20, 30), rgb(0.75f, 1.5f, 2.25f),  rgb(100, 100, 100)};
  storage_buffer<radiance> source(context(), input);
  storage_buffer<radiance> target(context(), input.size());
  image2d<glm::vec4> image(context(), 4, 2);
  pipeline.bind(pipeline.storage_array<radiance>("Input.values"), source);
  pipeline.bind(pipeline.storage_array<radiance>("target.scaled"), target);  // by instance name too
  pipeline.bind(pipeline.image<glm::vec4>("image"), image);

  block_data params = pipeline.block("Params");
  EXPECT_EQ(params.bytes().size(), 48u);  // std140: tint at 0, weights[2] at 16 with a stride of 16
  params.set(pipeline.member<radiance>("Params.tint"), rgb(0.25f, 0.5f, 1.0f));
  const std::array<float, 2> weights = {0.0f, 2.0f};
  params.set(pipeline.array_member<float>("params.weights"), weights);
  block_buffer params_buffer(context(), params);
  pipeline.bind(pipeline.block_binding("Params"), params_buffer);

  block_data push = pipeline.push_constants();
  EXPECT_EQ(push.bytes().size(), 8u);
  push.set(pipeline.push_constant<float>("factor"), 3.0f);
  push.set(pipeline.push_constant<std::uint32_t>("Push.count"), 7u);  // the last element is left alone
  pipeline.dispatch(push, 2);                                         // 2 workgroups of 4

  // Every value is exact in binary floating point: compared exactly.
  const std::vector<glm::vec3> expected = {{7, 14, 22}, {4, 3.5f, 4.75f}, {1, 2, 4},         {25, 50, 100},
                                           {-5, 8, -2}, {61, 122, 184},   {5.5f, 11, 17.5f}, {0, 0, 0}};
  const std::vector<radiance> scaled = target.read_back();
  const std::vector<glm::vec4> texels = image.read_back();
  ASSERT_EQ(scaled.size(), expected.size());
  ASSERT_EQ(texels.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(raw(scaled[i]), expected[i]);
    EXPECT_EQ(texels[i], glm::vec4(expected[i], i < 7 ? 1.0f : 0.0f));  // texel 7: never written, cleared to 0
  }
  EXPECT_EQ(raw(source.read_back()[3]), glm::vec3(4, 8, 16));  // the input is untouched
}

// Running again with other push constants and a new uniform block reuses the pipeline and its bindings.
TEST_F(ComputeTest, DispatchesAgainWithOtherPushConstants) {
  ComputePipeline pipeline(context(), test_shader("scale"), Specialization().set("gl_WorkGroupSize.x", 2u));
  const std::vector<radiance> input = {rgb(1, 1, 1), rgb(2, 2, 2)};
  storage_buffer<radiance> source(context(), input), target(context(), 2);
  image2d<glm::vec4> image(context(), 4, 1);
  pipeline.bind(pipeline.storage_array<radiance>("Input.values"), source);
  pipeline.bind(pipeline.storage_array<radiance>("Output.scaled"), target);
  pipeline.bind(pipeline.image<glm::vec4>("image"), image);
  block_data params = pipeline.block("Params");
  block_buffer params_buffer(context(), params);  // all zero: no tint
  pipeline.bind(pipeline.block_binding("Params"), params_buffer);
  const auto factor = pipeline.push_constant<float>("factor");
  block_data push = pipeline.push_constants();
  push.set(pipeline.push_constant<std::uint32_t>("count"), 2u);
  for (float f : {0.5f, 4.0f}) {
    push.set(factor, f);
    pipeline.dispatch(push, 1);
    const std::vector<radiance> scaled = target.read_back();
    EXPECT_EQ(raw(scaled[0]), glm::vec3(f));  // exposure keeps its default, 1
    EXPECT_EQ(raw(scaled[1]), glm::vec3(2 * f));
  }
  EXPECT_EQ(push.get(factor), 4.0f);
}

// triangles.sgl.comp: an array of std430 structs uploaded as the host laid
// it out (sizeof(Triangle) checked against the table's stride); a
// vector<world> push constant moves the scene, which changes no area.
TEST_F(ComputeTest, UploadsAnArrayOfStd430Structs) {
  ComputePipeline pipeline(context(), test_shader("triangles"));
  const std::vector<Triangle> scene = {
      {at(0, 0, 0), 0, at(2, 0, 0), 0, at(0, 3, 0), 0},
      {at(0, 0, 1), 0, at(1, 0, 1), 0, at(0, 1, 1), 1},
      {at(0, 0, 0), 0, at(4, 0, 0), 0, at(0, 0, 4), 2},
  };
  storage_buffer<Triangle> triangles(context(), scene);
  storage_buffer<area> areas(context(), scene.size());
  pipeline.bind(pipeline.storage_array<Triangle>("Triangles.triangles"), triangles);
  pipeline.bind(pipeline.storage_array<area>("Areas.areas"), areas);
  block_data frame = pipeline.push_constants();
  frame.set(pipeline.push_constant<world_vector>("offset"), from_raw<world_vector>(glm::vec3(0.5f, -2, 8)));
  pipeline.dispatch(frame, static_cast<std::uint32_t>(scene.size()));
  // area × (material + 1); length() may round in the last place: 1e-6 relative.
  const std::vector<float> expected = {3.0f, 1.0f, 24.0f};
  const std::vector<area> result = areas.read_back();
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_NEAR(raw(result[i]), expected[i], 1e-6f * expected[i]) << "triangle " << i;
}

// The same results through a whole storage block: sized by the table for a
// runtime-sized array of 3, bound by the block's name, read back member by member.
TEST_F(ComputeTest, ReadsARuntimeSizedStorageBlockBack) {
  ComputePipeline pipeline(context(), test_shader("triangles"));
  const std::vector<Triangle> scene = {{at(0, 0, 0), 0, at(2, 0, 0), 0, at(0, 3, 0), 0},
                                       {at(0, 0, 1), 0, at(1, 0, 1), 0, at(0, 1, 1), 1},
                                       {at(0, 0, 0), 0, at(4, 0, 0), 0, at(0, 0, 4), 2}};
  storage_buffer<Triangle> triangles(context(), scene);
  pipeline.bind(pipeline.storage_array<Triangle>("Triangles.triangles"), triangles);
  block_data areas = pipeline.block("Areas", scene.size());
  EXPECT_EQ(areas.bytes().size(), 12u);  // std430: floats 4 bytes apart
  block_buffer areas_buffer(context(), areas);
  pipeline.bind(pipeline.block_binding("result"), areas_buffer);
  pipeline.dispatch(pipeline.push_constants(), static_cast<std::uint32_t>(scene.size()));
  areas_buffer.read(areas);
  const auto area_of = pipeline.array_member<area>("Areas.areas");
  const std::vector<float> expected = {3.0f, 1.0f, 24.0f};  // 1e-6 relative, as above
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_NEAR(raw(areas.get(area_of, i)), expected[i], 1e-6f * expected[i]) << "triangle " << i;
}

}  // namespace
}  // namespace safegi::vk
