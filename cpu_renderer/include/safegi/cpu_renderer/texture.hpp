// Image textures: linear RGB texels in a MIP pyramid, looked up bilinearly on
// one level, trilinearly between the two levels around a footprint, or by
// pbrt-v3's EWA over an elliptical footprint.
//
// Texel values are dimensionless numbers; what they mean is the caller's: a
// reflectance texture returns them as a Reflectance, an environment map
// multiplies them by a Radiance. Lookup coordinates (s, t) are in [0, 1) across
// the image with t = 0 at row 0; texel (x, y) covers [x/w, (x+1)/w) × [y/h, (y+1)/h)
// and its centre is at ((x + 0.5)/w, (y + 0.5)/h), as in pbrt's MIPMap.
#pragma once

#include <string_view>
#include <vector>

#include "safegi/cpu_renderer/image.hpp"
#include "safegi/cpu_renderer/types.hpp"

namespace safegi::render {

// How a file's numbers encode a reflectance: sRGB-encoded (8-bit images as
// painted; decoded to linear at load) or already linear (EXR, HDR, PFM).
enum class ColourSpace { srgb, linear };
// bilinear: the finest level only; trilinear: bilinear on the two MIP levels
// around the footprint, blended (pbrt's "trilinear"); ewa: a Gaussian over the
// footprint's ellipse, long along a grazing slope and narrow across it (pbrt-v3's default).
enum class TextureFilter { bilinear, trilinear, ewa };

// One of a footprint ellipse's semi-axes, in (s, t) units.
struct StExtent {
  Real s = 0, t = 0;
};
// Outside [0, 1): repeat, clamp to the edge texel, or black; a lat-long map
// repeats in s (longitude) and clamps in t (latitude).
enum class TextureWrap { repeat, clamp, black, longitude_latitude };

using Texel = spectrum<dim::dimensionless>;

// The sRGB transfer function's inverse (IEC 61966-2-1): an encoded value in
// [0, 1] to linear.
float srgb_to_linear(float encoded);

// Decodes an image read from a file (row 0 at the top, as read_image gives it) to linear values: sRGB-decoded when
// `space` is srgb, each value times `scale`, and its rows flipped when
// `flip_rows` (so that t = 0 becomes the bottom row, pbrt's texture convention).
Image to_linear_texels(Image image, ColourSpace space, float scale, bool flip_rows);

class MipMap {
 public:
  // Level 0 is `image`; each next level halves width and height (rounding up)
  // with a 2×2 box filter whose texels beyond an odd edge repeat the edge,
  // down to 1×1. Throws std::invalid_argument on an empty or inconsistent image.
  MipMap(Image image, TextureWrap wrap);

  int levels() const { return static_cast<int>(levels_.size()); }
  int width(int level) const { return levels_[level].width; }
  int height(int level) const { return levels_[level].height; }
  TextureWrap wrap() const { return wrap_; }

  // Texel (x, y) of `level`, with the wrap mode applied to x and y.
  Texel texel(int level, int x, int y) const;
  // Bilinear interpolation between the four texels around (s, t) on `level`.
  Texel bilinear(int level, Real s, Real t) const;
  // Trilinear: the footprint `width` is the lookup's extent in (s, t) units;
  // the level is log2(width × max(width(0), height(0))), i.e. the footprint
  // measured in texels of level 0, blended linearly between the two levels
  // around it; below level 0 bilinear on level 0, beyond the last the 1×1 texel.
  Texel trilinear(Real s, Real t, Real width) const;
  // pbrt-v3's EWA (MIPMap::Lookup): the ellipse with conjugate semi-axes `a`
  // and `b` around (s, t), its minor axis lengthened until the major one is at
  // most `max_anisotropy` times as long, filtered on the two levels around
  // the minor axis' length (where it spans about a texel) by a Gaussian of
  // the ellipse's radius (e^(−2r²) − e^(−2), r < 1), blended; a degenerate
  // ellipse reads bilinearly on level 0.
  Texel ewa(Real s, Real t, StExtent a, StExtent b, Real max_anisotropy) const;
  // The mean and the per-channel maximum of level 0.
  Texel average() const;
  Texel maximum() const;

 private:
  Texel ewa_on_level(int level, Real s, Real t, StExtent a, StExtent b) const;

  struct Level {
    int width = 0, height = 0;
    std::vector<float> rgb;  // texels stay float in every build
  };
  std::vector<Level> levels_;
  TextureWrap wrap_;
};

}  // namespace safegi::render
