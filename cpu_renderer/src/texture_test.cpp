// Texture filtering against values computed by hand: the MIP pyramid's box
// filter, bilinear weights around texel centres, wrap modes, the trilinear
// blend between levels, and the sRGB decoding of reflectance textures.
#include "safegi/cpu_renderer/texture.hpp"

#include <gtest/gtest.h>

namespace safegi::render {
namespace {

// Red channel r(x, y) = x + 4 y on a 4×2 image (row 0 on top), green 10 r, blue 0.
Image ramp() {
  Image image{4, 2, {}};
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) image.rgb.insert(image.rgb.end(), {float(x + 4 * y), float(10 * (x + 4 * y)), 0.0f});
  return image;
}

Real red(Texel t) { return sg::raw(t).r; }

TEST(MipMap, PyramidIsA2x2BoxDownToOneTexel) {
  MipMap map(ramp(), TextureWrap::repeat);
  ASSERT_EQ(map.levels(), 3);
  EXPECT_EQ(map.width(1), 2);
  EXPECT_EQ(map.height(1), 1);
  EXPECT_EQ(map.width(2), 1);
  EXPECT_FLOAT_EQ(red(map.texel(1, 0, 0)), (0 + 1 + 4 + 5) / 4.0f);
  EXPECT_FLOAT_EQ(red(map.texel(1, 1, 0)), (2 + 3 + 6 + 7) / 4.0f);
  EXPECT_FLOAT_EQ(red(map.texel(2, 0, 0)), 3.5f);
  EXPECT_FLOAT_EQ(sg::raw(map.texel(2, 0, 0)).g, 35.0f);
  EXPECT_FLOAT_EQ(red(map.average()), 3.5f);
  EXPECT_FLOAT_EQ(red(map.maximum()), 7.0f);
}

TEST(MipMap, OddSizesRepeatTheirEdgeTexel) {
  Image image{3, 3, {}};
  for (int i = 0; i < 9; ++i) image.rgb.insert(image.rgb.end(), {float(i), 0.0f, 0.0f});
  MipMap map(std::move(image), TextureWrap::clamp);
  ASSERT_EQ(map.levels(), 3);  // 3×3, 2×2, 1×1
  EXPECT_FLOAT_EQ(red(map.texel(1, 0, 0)), (0 + 1 + 3 + 4) / 4.0f);
  EXPECT_FLOAT_EQ(red(map.texel(1, 1, 0)), (2 + 2 + 5 + 5) / 4.0f);
  EXPECT_FLOAT_EQ(red(map.texel(1, 1, 1)), 8.0f);
  EXPECT_FLOAT_EQ(red(map.texel(2, 0, 0)), (2.0f + 3.5f + 6.5f + 8.0f) / 4);
}

TEST(MipMap, BilinearWeighsTheFourTexelsAroundTheirCentres) {
  MipMap map(ramp(), TextureWrap::repeat);
  EXPECT_FLOAT_EQ(red(map.bilinear(0, 0.125f, 0.25f)), 0.0f);  // texel (0, 0)'s centre
  EXPECT_FLOAT_EQ(red(map.bilinear(0, 0.875f, 0.75f)), 7.0f);  // texel (3, 1)'s centre
  EXPECT_FLOAT_EQ(red(map.bilinear(0, 0.5f, 0.5f)), (1 + 2 + 5 + 6) / 4.0f);
  // A quarter of the way from texel (1, 0) to (2, 0), half way down to row 1.
  EXPECT_FLOAT_EQ(red(map.bilinear(0, 0.4375f, 0.5f)), 0.75f * 3 + 0.25f * 4);
  EXPECT_FLOAT_EQ(red(map.bilinear(0, 0.25f, 0.25f)), 0.5f);
}

TEST(MipMap, WrapModes) {
  // s = 1 + 1/8 is texel 4 on level 0: texel 0 repeated, texel 3 clamped, black outside.
  EXPECT_FLOAT_EQ(red(MipMap(ramp(), TextureWrap::repeat).bilinear(0, 1.125f, 0.25f)), 0.0f);
  EXPECT_FLOAT_EQ(red(MipMap(ramp(), TextureWrap::clamp).bilinear(0, 1.125f, 0.25f)), 3.0f);
  EXPECT_FLOAT_EQ(red(MipMap(ramp(), TextureWrap::black).bilinear(0, 1.0f, 0.25f)), 1.5f);  // half texel 3, half black
  // Longitude repeats, latitude clamps: across the top edge it stays on row 0.
  MipMap lat_long(ramp(), TextureWrap::longitude_latitude);
  EXPECT_FLOAT_EQ(red(lat_long.bilinear(0, 1.125f, 0.25f)), 0.0f);
  EXPECT_FLOAT_EQ(red(lat_long.bilinear(0, 0.125f, -0.5f)), 0.0f);
  EXPECT_FLOAT_EQ(red(lat_long.bilinear(0, 0.0f, 0.25f)), 1.5f);  // the seam blends texels 3 and 0
}

TEST(MipMap, TrilinearBlendsTheLevelsAroundTheFootprint) {
  MipMap map(ramp(), TextureWrap::repeat);
  // At (1/4, 1/4): level 0 gives 0.5; level 1 (2×1) gives texel (0, 0) = 2.5.
  EXPECT_FLOAT_EQ(red(map.trilinear(0.25f, 0.25f, 0.1f / 4)), 0.5f);  // footprint below a texel: level 0
  EXPECT_FLOAT_EQ(red(map.trilinear(0.25f, 0.25f, 2.0f / 4)), 2.5f);  // two texels: level 1
  EXPECT_NEAR(red(map.trilinear(0.25f, 0.25f, std::sqrt(2.0f) / 4)), 0.5f * 0.5f + 0.5f * 2.5f, 1e-6f);  // level 0.5
  EXPECT_FLOAT_EQ(red(map.trilinear(0.25f, 0.25f, 8.0f / 4)), 3.5f);  // the whole image: the 1×1 level
}

TEST(Texture, SrgbDecodingAndRowFlip) {
  EXPECT_EQ(srgb_to_linear(0), 0);
  EXPECT_FLOAT_EQ(srgb_to_linear(1), 1);
  EXPECT_FLOAT_EQ(srgb_to_linear(0.04045f), 0.04045f / 12.92f);
  EXPECT_NEAR(srgb_to_linear(0.5f), 0.2140411f, 1e-6f);
  Image linear = to_linear_texels(ramp(), ColourSpace::linear, 0.5f, true);
  EXPECT_FLOAT_EQ(linear.rgb[0], 2.0f);  // row 1 (x + 4) is now on top, halved
  EXPECT_FLOAT_EQ(linear.rgb[3 * 4], 0.0f);
  Image decoded = to_linear_texels(Image{1, 1, {0.5f, 1.0f, 2.0f}}, ColourSpace::srgb, 1.0f, false);
  EXPECT_NEAR(decoded.rgb[0], 0.2140411f, 1e-6f);
  EXPECT_FLOAT_EQ(decoded.rgb[2], 1.0f);  // encoded values beyond 1 clamp
  EXPECT_THROW(MipMap(Image{2, 2, {1, 2, 3}}, TextureWrap::repeat), std::invalid_argument);
}

}  // namespace
}  // namespace safegi::render
