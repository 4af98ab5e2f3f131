#include "safegi/runtime_gl/resources.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "safegi/symbol_table/error.hpp"
#include "safegi/runtime_gl/gl.hpp"
#include "test_gl.hpp"

namespace safegi::gl {
namespace {

class ResourcesTest : public testing::GlTest {};

template <class T>
std::vector<T> ramp(int count) {
  std::vector<T> values;
  for (int i = 0; i < count; ++i) values.push_back(T(static_cast<typename T::value_type>(i * 3 + 1)) * T(1));
  return values;
}

template <class T>
void expect_round_trip(const std::vector<T>& texels, int width, int height) {
  texture2d<T> texture(width, height, std::span<const T>(texels));
  EXPECT_EQ(texture.read_back(), texels);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(ResourcesTest, TexturesRoundTripEveryTexelType) {
  expect_round_trip(std::vector<float>{0.5f, -1e-30f, 1e30f, 3.0f, 0.0f, -7.25f}, 3, 2);
  expect_round_trip(ramp<glm::vec2>(6), 2, 3);
  expect_round_trip(ramp<glm::vec3>(5), 5, 1);  // stored as RGBA, read back as RGB
  expect_round_trip(ramp<glm::vec4>(4), 2, 2);
  expect_round_trip(ramp<glm::ivec3>(3), 1, 3);
  expect_round_trip(ramp<glm::uvec2>(8), 4, 2);
  expect_round_trip(std::vector<std::int32_t>{-5, 7, 2147483647}, 3, 1);
}

TEST_F(ResourcesTest, TextureUploadsMustFillTheTexture) {
  texture2d<glm::vec2> texture(2, 2);
  std::vector<glm::vec2> three(3);
  try {
    texture.upload(three);
    FAIL();
  } catch (const ResourceError& error) {
    EXPECT_STREQ(error.what(), "safegi::gl: texture2d upload of 3 texels into a 2x2 texture");
  }
}

TEST_F(ResourcesTest, FramebufferAttachmentsMustMatchItsSize) {
  texture2d<glm::vec4> texture(2, 2);
  framebuffer target(4, 4);
  try {
    target.attach(output_id<glm::vec4>{0}, texture);
    FAIL();
  } catch (const ResourceError& error) {
    EXPECT_STREQ(error.what(), "safegi::gl: a 2x2 texture attached to a 4x4 framebuffer");
  }
}

TEST_F(ResourcesTest, AnIncompleteFramebufferSaysWhy) {
  framebuffer empty(2, 2);
  try {
    empty.bind();
    FAIL();
  } catch (const ResourceError& error) {
    EXPECT_STREQ(error.what(),
                 "safegi::gl: framebuffer incomplete: GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT (nothing attached)");
  }
}

TEST_F(ResourcesTest, AFramebufferClearsIntoItsTypedAttachment) {
  texture2d<glm::vec4> texture(2, 2);
  framebuffer target(2, 2);
  target.attach(output_id<glm::vec4>{0}, texture);
  target.add_depth();
  target.bind();
  glClearColor(0.25f, 0.5f, 1.0f, 2.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  for (const glm::vec4& texel : texture.read_back()) EXPECT_EQ(texel, glm::vec4(0.25f, 0.5f, 1.0f, 2.0f));
}

TEST_F(ResourcesTest, ResourcesMoveAndFreeTheirNames) {
  texture2d<float> first(1, 1);
  const unsigned name = first.id();
  texture2d<float> second = std::move(first);
  EXPECT_EQ(second.id(), name);
  EXPECT_TRUE(glIsTexture(name));
  { texture2d<float> gone = std::move(second); }
  EXPECT_FALSE(glIsTexture(name));
}

}  // namespace
}  // namespace safegi::gl
