// The generated handles header (safegi-gl-handles --api vulkan, made at build
// time from scale.sgl.comp's table): its typed handles drive the pipeline, and
// a host struct mirroring the push-constant block is checked against its
// layout at compile time.
#include <gtest/gtest.h>

#include <vector>

#include "scale_handles.hpp"
#include "test_types.hpp"
#include "test_vk.hpp"

namespace safegi::vk {
namespace {

using namespace testing;
namespace layout = shaders::scale::layout;

struct PushHost {
  float factor;
  std::uint32_t count;
};
SAFEGI_VK_EXPECT_MEMBER(PushHost, factor, layout::Push::factor);
SAFEGI_VK_EXPECT_MEMBER(PushHost, count, layout::Push::count);
SAFEGI_VK_EXPECT_SLOT(layout::Params, 1, 0);
SAFEGI_VK_EXPECT_SLOT(layout::Output, 0, 1);
static_assert(layout::Params::weights::stride == 16 && layout::Params::block_size == 48);  // std140

class HandlesUsageTest : public VulkanTest {};

TEST_F(HandlesUsageTest, GeneratedHandlesDriveThePipeline) {
  ComputePipeline pipeline(context(), test_shader("scale"),
                           Specialization().set(shaders::scale::constants::gl_WorkGroupSize_x, 2u));
  const shaders::scale::Handles handles(pipeline);
  storage_buffer<radiance> source(context(), std::vector<radiance>{rgb(1, 2, 3), rgb(4, 5, 6)});
  storage_buffer<radiance> target(context(), 2);
  image2d<glm::vec4> image(context(), 4, 1);
  pipeline.bind(handles.Input_values, source);
  pipeline.bind(handles.Output_scaled, target);
  pipeline.bind(pipeline.image<glm::vec4>("image"), image);
  block_data params = pipeline.block("Params");
  params.set(handles.Params_tint, rgb(1, 1, 1));
  params.set(handles.Params_weights, std::vector<float>{0, 0.5f});
  block_buffer params_buffer(context(), params);
  pipeline.bind(handles.Params, params_buffer);
  block_data push = pipeline.push_constants();
  push.copy_from(PushHost{2.0f, 2u});
  EXPECT_EQ(push.get(handles.Push_factor), 2.0f);
  pipeline.dispatch(push, 1);
  const std::vector<radiance> scaled = target.read_back();
  EXPECT_EQ(raw(scaled[0]), glm::vec3(2.5f, 4.5f, 6.5f));  // exact: (x * 2 + 1 * 0.5) * 1
  EXPECT_EQ(raw(scaled[1]), glm::vec3(8.5f, 10.5f, 12.5f));
}

TEST_F(HandlesUsageTest, AStaleHeaderIsRefused) {
  ComputePipeline pipeline(context(), test_shader("scale"));
  const std::string hash = pipeline.stage().source_hash;
  ASSERT_FALSE(hash.empty());
  EXPECT_EQ(error_of([&] { pipeline.expect_source_hash("fnv1a64:0000000000000000"); }),
            "scale.sgl.comp: error: the handles were generated from another version of this shader (source hash "
            "fnv1a64:0000000000000000, the table says " +
                hash + "); regenerate them");
  EXPECT_EQ(error_of([&] { pipeline.expect_source_hash(hash); }), "no error");
}

}  // namespace
}  // namespace safegi::vk
