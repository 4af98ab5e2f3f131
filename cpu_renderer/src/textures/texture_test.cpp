// Texture filtering against values computed by hand: the MIP pyramid's box
// filter, bilinear weights around texel centres, wrap modes, the trilinear
// blend between levels, the sRGB decoding of reflectance textures, and a ray
// cone's extent in (u, v).
#include "safegi/cpu_renderer/texture.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "textures/surface_texture.hpp"

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

// A 64² image whose texels follow `value(x, y)`.
MipMap pattern_map(float (*value)(int x, int y)) {
  Image image{64, 64, {}};
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      for (int c = 0; c < 3; ++c) image.rgb.push_back(value(x, y));
  return MipMap(std::move(image), TextureWrap::repeat);
}

// EWA filters along the ellipse's long axis only: 16 texels along s average
// one-texel columns to their mean, while bands 8 texels tall stay their own
// value across its one-texel minor axis (trilinear, isotropic over the long
// axis, blurs them both). A constant stays itself; a degenerate ellipse reads
// level 0 bilinearly; a needle is widened to 1/max_anisotropy of its length.
TEST(MipMap, EwaFiltersAlongTheEllipseOnly) {
  const MipMap columns = pattern_map([](int x, int) { return static_cast<float>(x % 2); });
  const MipMap bands = pattern_map([](int, int y) { return static_cast<float>((y / 8) % 2 == 0); });
  const Real s = 20.5f / 64, t = 3.5f / 64;  // a texel centre, in a band of 1s
  const StExtent along{16.0f / 64, 0}, across{0, 1.0f / 64};
  EXPECT_NEAR(sg::raw(columns.ewa(s, t, along, across, 16)).x, 0.5, 0.03);
  EXPECT_NEAR(sg::raw(bands.ewa(s, t, along, across, 16)).x, 1.0, 1e-6);
  EXPECT_LT(sg::raw(bands.trilinear(s, t, 16.0f / 64)).x, 0.8f);
  const MipMap grey = pattern_map([](int, int) { return 0.25f; });
  EXPECT_NEAR(sg::raw(grey.ewa(s, t, along, StExtent{0.3f, 0.2f}, 8)).x, 0.25, 1e-6);
  EXPECT_EQ(sg::raw(columns.ewa(s, t, along, StExtent{}, 8)), sg::raw(columns.bilinear(0, s, t)));
  // 32 texels along s, half a texel across: clamped to 4 across, level 2, where the columns are grey.
  EXPECT_NEAR(sg::raw(columns.ewa(s, t, StExtent{0.5f, 0}, StExtent{0, 0.5f / 64}, 8)).x, 0.5, 1e-6);
  // A diagonal needle with no anisotropy limit: read on a coarser level (grey), not texel by texel along it.
  const Real needle = sg::raw(bands.ewa(s, t, StExtent{0.7f, 0.7f}, StExtent{1e-6f, -1e-6f}, 1e6f)).x;
  EXPECT_GE(needle, 0.0f);
  EXPECT_LE(needle, 1.0f);
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

// A cone 0.1 m wide meets the plane z = 0, where u runs 2 m along x and v
// 2 m along y: head on, 0.05 in each; tilted 60 degrees towards x, stretched
// to 0.1 in u only; towards y, in v only; with (u, v) turned 45 degrees, the
// ellipse's two axes each reach both, the long one deciding.
TEST(ConeFootprint, ItsExtentInUAndVFollowsTheSlope) {
  const Length metre = Real(1) * units::meter;
  const NormalWorld up(0, 0, 1);
  const Real c = std::cos(Real(1.0471976)), s = std::sin(Real(1.0471976));
  auto extent = [&](VectorWorld dp_du, VectorWorld dp_dv, DirectionWorld direction) {
    return cone_uv_extent(dp_du, dp_dv, cone_axes_on_surface(up, ConeFootprint{Real(0.1) * metre, direction})).value();
  };
  const VectorWorld along_x(2 * metre, 0 * metre, 0 * metre), along_y(0 * metre, 2 * metre, 0 * metre);
  auto [head_on_u, head_on_v] = extent(along_x, along_y, DirectionWorld(0, 0, -1));
  EXPECT_NEAR(head_on_u, 0.05f, 1e-6f);
  EXPECT_NEAR(head_on_v, 0.05f, 1e-6f);
  auto [x_u, x_v] = extent(along_x, along_y, DirectionWorld(s, 0, -c));
  EXPECT_NEAR(x_u, 0.1f, 1e-5f);
  EXPECT_NEAR(x_v, 0.05f, 1e-6f);
  auto [y_u, y_v] = extent(along_x, along_y, DirectionWorld(0, -s, -c));
  EXPECT_NEAR(y_u, 0.05f, 1e-6f);
  EXPECT_NEAR(y_v, 0.1f, 1e-5f);
  const Real h = std::sqrt(Real(0.5));
  const VectorWorld diagonal_u(2 * h * metre, 2 * h * metre, 0 * metre), diagonal_v(-2 * h * metre, 2 * h * metre, 0 * metre);
  auto [d_u, d_v] = extent(diagonal_u, diagonal_v, DirectionWorld(s, 0, -c));
  EXPECT_NEAR(d_u, 0.1f * h, 1e-5f);
  EXPECT_NEAR(d_v, 0.1f * h, 1e-5f);
  // dp/du parallel to dp/dv: no frame to write the ellipse in.
  EXPECT_FALSE(cone_uv_extent(along_x, along_x, cone_axes_on_surface(up, ConeFootprint{Real(0.1) * metre, DirectionWorld(0, 0, -1)})));
}

// With the image's pixel steps, the axes on the surface are where rays that
// far apart meet its plane (pbrt-v3's differentials): each step slid along the
// ray onto the plane, to first order the offset ray's own hit, found here by
// intersecting it. Across the slope a step stays itself; the box extents then
// follow the steps, not the ellipse's own axes.
TEST(ConeFootprint, PixelStepsLandWhereNeighbouringRaysMeetThePlane) {
  const Length metre = Real(1) * units::meter;
  const NormalWorld up(0, 0, 1);
  const glm::vec3 d = glm::normalize(glm::vec3(0.6f, 0.2f, -0.7f));
  const glm::vec3 e = glm::normalize(glm::vec3(0.3f, -0.5f, 0) - d * glm::dot(d, glm::vec3(0.3f, -0.5f, 0)));
  const glm::vec3 e_across = glm::normalize(glm::cross(d, glm::vec3(0, 0, 1)));
  ConeFootprint footprint{Real(0.01) * metre, sg::from_raw<DirectionWorld>(d)};
  footprint.step_x = sg::from_raw<ConeStep>(e * 0.8f);
  footprint.step_y = sg::from_raw<ConeStep>(e_across);
  const std::array<Real3, 2> axes = cone_axes_on_surface(up, footprint);
  // Rays from 3 m above the origin's hit: the central one and one turned by 0.01 · 0.8 · e per metre travelled.
  const glm::vec3 origin = -d * (3.0f / -d.z);
  auto hit_of = [&](glm::vec3 direction) { return origin + direction * (-origin.z / direction.z); };
  const float travelled = 3.0f / -d.z;
  const glm::vec3 offset_hit = hit_of(d + e * (0.8f * 0.01f / travelled));
  EXPECT_NEAR(axes[0].x, offset_hit.x, 2e-5f);
  EXPECT_NEAR(axes[0].y, offset_hit.y, 2e-5f);
  EXPECT_NEAR(axes[0].z, 0.0f, 1e-7f);
  EXPECT_NEAR(axes[1].x, 0.01f * e_across.x, 1e-7f);
  EXPECT_NEAR(axes[1].y, 0.01f * e_across.y, 1e-7f);
  const VectorWorld along_x(2 * metre, 0 * metre, 0 * metre), along_y(0 * metre, 2 * metre, 0 * metre);
  auto [u, v] = cone_uv_extent(along_x, along_y, axes).value();
  EXPECT_NEAR(u, std::max(std::abs(axes[0].x), std::abs(axes[1].x)) / 2, 1e-7f);
  EXPECT_NEAR(v, std::max(std::abs(axes[0].y), std::abs(axes[1].y)) / 2, 1e-7f);
}

}  // namespace
}  // namespace safegi::render
