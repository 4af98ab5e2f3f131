// The checked build's named errors: each mismatch between the host and the
// symbol table, with its exact message (the shader's file:line:col, the
// member, what the shader declares and what the host gives).
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "test_types.hpp"
#include "test_vk.hpp"

// A triangle without its padding: 40 bytes where the shader's std430 array strides 48.
struct PackedTriangle {
  glm::vec3 a, b, c;
  std::uint32_t material;
};
template <>
struct safegi::vk::std430_struct<PackedTriangle> {
  static constexpr std::string_view glsl_name = "Triangle";
};

namespace safegi::vk {
namespace {

using namespace testing;
using irradiance = spectrum<dim::irradiance>;

class BindingErrorsTest : public VulkanTest {
 protected:
  void SetUp() override {
    scale_ = std::make_unique<ComputePipeline>(context(), test_shader("scale"));
    triangles_ = std::make_unique<ComputePipeline>(context(), test_shader("triangles"));
  }
  std::unique_ptr<ComputePipeline> scale_, triangles_;
};

TEST_F(BindingErrorsTest, Dimension) {
  EXPECT_EQ(error_of([&] { scale_->push_constant<quantity<dim::length>>("factor"); }),
            "scale.sgl.comp:19:14: error: push-constant member 'Push.factor' is declared with type "
            "float but the host uses float<length> (kind and dimension differ)");
  EXPECT_EQ(error_of([&] { scale_->storage_array<irradiance>("Input.values"); }),
            "scale.sgl.comp:11:81: error: storage array 'Input.values' is declared with type "
            "spectrum<radiance> but the host uses spectrum<irradiance> (dimension differs)");
  EXPECT_EQ(error_of([&] { scale_->member<irradiance>("Params.tint"); }),
            "scale.sgl.comp:15:24: error: block member 'Params.tint' is declared with type "
            "spectrum<radiance> but the host uses spectrum<irradiance> (dimension differs)");
  EXPECT_EQ(error_of([&] { triangles_->storage_array<quantity<dim::length>>("Areas.areas"); }),
            "triangles.sgl.comp:18:75: error: storage array 'Areas.areas' is declared with type "
            "float<area> but the host uses float<length> (dimension differs)");
}

TEST_F(BindingErrorsTest, Space) {
  EXPECT_EQ(error_of([&] { triangles_->push_constant<vector<spaces::camera>>("offset"); }),
            "triangles.sgl.comp:20:53: error: push-constant member 'Frame.offset' is declared with "
            "type vector<world> but the host uses vector<camera> (space differs)");
  EXPECT_EQ(error_of([&] { triangles_->push_constant<world_point>("offset"); }),
            "triangles.sgl.comp:20:53: error: push-constant member 'Frame.offset' is declared with "
            "type vector<world> but the host uses point<world> (kind and dimension differ)");
}

TEST_F(BindingErrorsTest, SetAndBinding) {
  block_data params = scale_->block("Params");
  block_buffer buffer(context(), params);
  // Another pipeline's handle: its block is another slot of another table.
  EXPECT_EQ(error_of([&] { triangles_->bind(scale_->block_binding("Params"), buffer); }),
            "triangles: error: the handle of set 1, binding 0 was not looked up in this pipeline");
  EXPECT_EQ(error_of([&] { scale_->block_binding("Nothing"); }),
            "scale: error: no uniform or storage block named 'Nothing' in scale.sgl.comp");
}

TEST_F(BindingErrorsTest, OffsetAndStride) {
  EXPECT_EQ(error_of([&] { triangles_->storage_array<PackedTriangle>("Triangles.triangles"); }),
            "triangles.sgl.comp:17:75: error: storage array 'Triangles.triangles' has an array stride of 48 bytes in "
            "the shader but 40 on the host (sizeof(Triangle))");
  EXPECT_EQ(error_of([&] { triangles_->storage_array<glm::vec4>("Triangles.triangles"); }),
            "triangles.sgl.comp:17:75: error: storage array 'Triangles.triangles' is declared with "
            "type Triangle but the host uses vec4 (GLSL type differs)");
  EXPECT_EQ(error_of([&] { scale_->storage_array<float>("Params.weights"); }),
            "scale.sgl.comp:16:14: error: storage array 'Params.weights' is in uniform block 'Params'; "
            "a storage_buffer binds to a buffer block");
  EXPECT_EQ(error_of([&] { scale_->member<float>("Params.weights"); }),
            "scale.sgl.comp:16:14: error: block member 'Params.weights' is an array of 2; look it up "
            "with array_member<T>");
  EXPECT_EQ(error_of([&] { scale_->array_member<radiance>("Params.tint"); }),
            "scale.sgl.comp:15:24: error: block member 'Params.tint' is not an array; look it up with "
            "member<T>");
}

TEST_F(BindingErrorsTest, Size) {
  block_data params = scale_->block("Params");
  const std::array<float, 3> three = {1, 2, 3};
  EXPECT_EQ(error_of([&] { params.set(scale_->array_member<float>("Params.weights"), three); }),
            "safegi::vk: block 'Params': 3 values for an array of 2");
  block_data push = scale_->push_constants();
  EXPECT_EQ(error_of([&] { push.set(triangles_->push_constant<world_vector>("offset"), world_vector{}); }),
            "safegi::vk: block 'Push' (symbol 4) used through a handle of another block (symbol 2); "
            "look the handle up in the pipeline and block the data was made for");
  EXPECT_EQ(error_of([&] { scale_->push_constant<glm::vec2>("factor"); }),
            "scale.sgl.comp:19:14: error: push-constant member 'Push.factor' is declared with type "
            "float but the host uses vec2 (GLSL type differs)");
}

TEST_F(BindingErrorsTest, MissingNames) {
  EXPECT_EQ(error_of([&] { scale_->push_constant<float>("gain"); }),
            "scale: error: no push-constant member named 'gain' in scale.sgl.comp");
  EXPECT_EQ(error_of([&] { scale_->member<radiance>("Params.tnit"); }),
            "scale: error: no block member named 'Params.tnit' in scale.sgl.comp");
  EXPECT_EQ(error_of([&] { scale_->image<glm::vec4>("picture"); }),
            "scale: error: no image named 'picture' in scale.sgl.comp");
  EXPECT_EQ(error_of([&] { scale_->image<glm::vec4>("Params"); }),
            "scale.sgl.comp:14:38: error: 'Params' is a block, not a storage image2D");
}

TEST_F(BindingErrorsTest, SpecializationConstants) {
  EXPECT_EQ(error_of([&] { ComputePipeline(context(), test_shader("scale"), Specialization().set("exposure", 2u)); }),
            "scale.sgl.comp:8:37: error: specialization constant 'exposure' is declared with type "
            "float but the host uses uint (GLSL type differs)");
  EXPECT_EQ(error_of([&] { ComputePipeline(context(), test_shader("scale"), Specialization().set("gain", 2.0f)); }),
            "scale: error: no specialization constant named 'gain' in scale.sgl.comp (it declares "
            "gl_WorkGroupSize.x (id 0), exposure (id 1), row_length (id 2))");
  EXPECT_EQ(error_of([&] { ComputePipeline(context(), test_shader("scale"), Specialization().set(9u, 2.0f)); }),
            "scale: error: no specialization constant with id 9 in scale.sgl.comp (it declares "
            "gl_WorkGroupSize.x (id 0), exposure (id 1), row_length (id 2))");
  EXPECT_EQ(error_of([&] {
              ComputePipeline(context(), test_shader("scale"),
                              Specialization().set("exposure", quantity<dim::length>{}));
            }),
            "scale.sgl.comp:8:37: error: specialization constant 'exposure' is declared with type "
            "float but the host uses float<length> (kind and dimension differ)");
}

TEST_F(BindingErrorsTest, Dispatch) {
  EXPECT_EQ(error_of([&] { scale_->dispatch(scale_->push_constants(), 1); }),
            "scale: error: dispatch with 'Input' (set 0, binding 0) unbound");
  EXPECT_EQ(error_of([&] { triangles_->dispatch(1); }),
            "triangles: error: the shader has push constants ('Frame'); dispatch with push_constants()");
}

TEST_F(BindingErrorsTest, ShaderAndTable) {
  ComputeShader opengl = test_shader("scale");
  opengl.symbols.stages[0].client = gl::Client::opengl;
  EXPECT_EQ(error_of([&] { ComputePipeline(context(), opengl); }),
            "scale.sgl.comp: error: the stage was compiled for OpenGL; a Vulkan pipeline needs the "
            "table safeglslc writes with -V or --target-env vulkan1.x");
  ComputeShader truncated = test_shader("scale");
  truncated.spirv.resize(3);
  EXPECT_EQ(error_of([&] { ComputePipeline(context(), truncated); }), "scale: error: not a SPIR-V module (3 words)");
}

}  // namespace
}  // namespace safegi::vk
