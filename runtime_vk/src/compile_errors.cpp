// Mistakes that must not compile, one per CASE (runtime_vk's CMakeLists runs
// the compiler on this file with -DCASE=N and expects the error it names).
#include <array>
#include <vector>

#include "scale_handles.hpp"
#include "test_types.hpp"
#include "triangles_handles.hpp"

using namespace safegi;
using namespace safegi::vk;
using namespace safegi::vk::testing;
namespace layout = shaders::scale::layout;

// An array of structs checked field by field against the table's fields (the control, CASE 0: the
// test's own Triangle, 48 bytes).
using fields = shaders::triangles::layout::Triangles::triangles::fields;
SAFEGI_VK_EXPECT_MEMBER(Triangle, a, fields::a);
SAFEGI_VK_EXPECT_MEMBER(Triangle, c, fields::c);
SAFEGI_VK_EXPECT_MEMBER(Triangle, material, fields::material);

#if CASE == 1  // a push constant of another dimension
void wrong_dimension(block_data& push, const shaders::scale::Handles& handles) {
  push.set(handles.Push_factor, quantity<dim::length>{});
}
#elif CASE == 2  // a buffer of irradiance bound where the shader reads radiance
void wrong_buffer(ComputePipeline& pipeline, const shaders::scale::Handles& handles,
                  const storage_buffer<spectrum<dim::irradiance> >& buffer) {
  pipeline.bind(handles.Input_values, buffer);
}
#elif CASE == 3  // a host struct whose field lies at another offset
struct PushHost {
  float factor;
  float padding;
  std::uint32_t count;
};
SAFEGI_VK_EXPECT_MEMBER(PushHost, count, layout::Push::count);
#elif CASE == 4  // a host struct whose field has another dimension
struct PushHost {
  quantity<dim::time> factor;
  std::uint32_t count;
};
SAFEGI_VK_EXPECT_MEMBER(PushHost, factor, layout::Push::factor);
#elif CASE == 5  // a std140 array mirrored with the std430 stride: another size
struct ParamsHost {
  radiance tint;
  float pad;
  std::array<float, 2> weights;
};
SAFEGI_VK_EXPECT_MEMBER(ParamsHost, weights, layout::Params::weights);
#elif CASE == 6  // a hand-written binding that is not the shader's
SAFEGI_VK_EXPECT_SLOT(layout::Params, 0, 2);
#elif CASE == 8  // a triangle's corner in object space where the shader's are in world space
struct TriangleHost {
  world_point a;
  float pad0;
  point<spaces::object> b;
};
SAFEGI_VK_EXPECT_MEMBER(TriangleHost, b, fields::b);
#elif CASE == 9  // the std430 padding forgotten: material at byte 36, not 44
struct TriangleHost {
  world_point a, b, c;
  std::uint32_t material;
};
SAFEGI_VK_EXPECT_MEMBER(TriangleHost, material, fields::material);
#elif CASE == 7  // a vec3 storage image: Vulkan has no such storage format
image2d<glm::vec3>* wrong_image = nullptr;
void touch() { (void)wrong_image->width(); }
#endif
