// Procedural reflectance textures: pbrt-v3's checkerboards, dots, and the
// noise patterns (fbm, wrinkled, windy, marble), evaluated as pbrt-v3 does.
//
// A 2D pattern reads the hit's (u, v) through a uv mapping; a solid one reads
// the hit's position in its texture space: the space the scene file's
// transform stood for where the texture was declared, measured in the scene
// file's own length unit (pbrt-v3's IdentityMapping3D). Every value is a
// reflectance, clamped to [0, 1] (pbrt-v3 clamps materials' reflectances
// below 0; above 1 a surface would reflect more than it receives).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <variant>

#include "safegi/cpu_renderer/types.hpp"

namespace safegi::render {

struct TextureSpace : space_tag<"texture"> {};
using TextureFromRender = map<World, TextureSpace>;

// Where a solid pattern reads a point: its texture-space position over `unit`.
struct SolidMapping {
  TextureFromRender texture_from_render;
  Length unit = Real(1) * units::metre;  // one texture-space unit: the scene file's length unit
  Real stretch = 1.0f;                // how the map scales lengths (∛|det|), for footprints
  // The point's texture-space coordinates, in `unit`s.
  sg::vec3_rep coordinates(PointWorld position) const;
};

// A 2D texture's coordinates.
struct TextureCoordinates {
  Real s = 0.0f, t = 0.0f;
};

// pbrt-v3's TextureMapping2D: where a surface point reads a 2D texture.
//   uv:          (s, t) = (u · u_scale + u_offset, v · v_scale + v_offset)
//   spherical:   the direction d of the point from texture space's origin: (θ/π, φ/2π)
//   cylindrical: (π + atan2(d.y, d.x)) / 2π, d.z
//   planar:      (u_offset + p · s_axis, v_offset + p · t_axis), p the point in the
//                scene file's world, in its length unit (pbrt-v3's PlanarMapping2D)
struct Mapping2D {
  enum class Kind : std::uint8_t { uv, spherical, cylindrical, planar };
  Kind kind = Kind::uv;
  Real u_scale = 1.0f, v_scale = 1.0f, u_offset = 0.0f, v_offset = 0.0f;
  SolidMapping space;  // spherical, cylindrical: texture space; planar: the scene file's world
  sg::vec3_rep s_axis{1, 0, 0}, t_axis{0, 1, 0};

  TextureCoordinates at(Real u, Real v, PointWorld position) const;
  // How far (s, t) moves per unit of the surface's (u, v), for footprints;
  // zero where it does not follow (u, v): those lookups are unfiltered.
  Real uv_scale() const;
};

// Alternating squares of side 1 in (s, t): `even` where ⌊s⌋ + ⌊t⌋ is even.
// Box-filtered over the footprint in closed form (pbrt-v3's "closedform"), or
// point-sampled (its "none").
struct CheckerboardPattern {
  Mapping2D mapping;
  Reflectance even{}, odd{};
  bool box_filtered = true;
};
// Unit cubes in texture space: `even` where ⌊x⌋ + ⌊y⌋ + ⌊z⌋ is even.
struct SolidCheckerboardPattern {
  SolidMapping mapping;
  Reflectance even{}, odd{};
};
// A dot of radius 0.35 in about half the unit cells of (s, t), placed by noise.
struct DotsPattern {
  Mapping2D mapping;
  Reflectance inside{}, outside{};
};
// Grey of fractional Brownian motion (`fbm`) or turbulence (`wrinkled`).
struct FbmPattern {
  SolidMapping mapping;
  Real omega = 0.5f;  // pbrt's "roughness": each octave's amplitude over the last's
  int octaves = 8;
  bool turbulence = false;  // pbrt's "wrinkled"
};
// pbrt-v3's "windy": waves whose height a slower noise modulates.
struct WindyPattern {
  SolidMapping mapping;
};
// Veins: a sine of y plus `variation` times fbm, through pbrt-v3's colour spline.
struct MarblePattern {
  SolidMapping mapping;
  Real omega = 0.5f;
  int octaves = 8;
  Real scale = 1.0f;  // on the texture-space position
  Real variation = 0.2f;
};

// pbrt-v3's UVTexture: the lookup's (s − ⌊s⌋, t − ⌊t⌋, 0).
struct UvPattern {
  Mapping2D mapping;
};
// pbrt-v3's BilerpTexture: v00 (1 − s)(1 − t) + v01 (1 − s) t + v10 s (1 − t) + v11 s t.
struct BilerpPattern {
  Mapping2D mapping;
  Reflectance v00{}, v01{}, v10{}, v11{};
};

struct ProceduralTexture;
// A texture inside another: a constant, times a pattern where there is one.
struct PatternOperand {
  Reflectance value{1.0f};
  std::shared_ptr<const ProceduralTexture> pattern;  // null: the constant alone
};
// pbrt-v3's MixTexture, (1 − amount) · first + amount · second (amount a float
// texture: grey), and its ScaleTexture of two textures, first × second.
struct MixPattern {
  PatternOperand first, second, amount;
};
struct ProductPattern {
  PatternOperand first, second;
};

using Pattern = std::variant<CheckerboardPattern, SolidCheckerboardPattern, DotsPattern, FbmPattern, WindyPattern,
                             MarblePattern, UvPattern, BilerpPattern, MixPattern, ProductPattern>;

struct ProceduralTexture {
  std::string name;  // as declared (for messages)
  Pattern pattern;
};

// Where a surface is looked up: its (u, v) and how far u and v each move
// across the footprint; its position and the footprint's width (zero widths:
// no filtering).
struct PatternLookup {
  Real u = 0.0f, v = 0.0f;
  Real u_footprint = 0.0f, v_footprint = 0.0f;
  PointWorld position;
  Length width = sg::zero;
};

bool reads_uv(const Pattern& pattern);
// The reflectance at a lookup as pbrt-v3's textures give it: clamped below 0
// only (fbm's and wrinkled's sums of noise, and marble, can go above 1; the
// importer warns where they do).
Reflectance evaluate(const Pattern& pattern, const PatternLookup& at);
// The value of a float texture's pattern (its colours grey): unclamped, since
// a bump map's displacement may be negative (fbm's noise is) or above 1.
Real evaluate_number(const Pattern& pattern, const PatternLookup& at);
Reflectance evaluate_unclamped(const Pattern& pattern, const PatternLookup& at);
// Bounds for the importer's checks and the preview's colour: the largest value
// evaluate() gives (per channel) and its mean over many cells. The largest is
// a bound for the patterns of given colours, and for sums of noise octaves
// (fbm, wrinkled, windy) and marble the largest of 16³ point samples a unit
// apart (every octave), what such a texture reaches in practice.
Reflectance largest_value(const Pattern& pattern);
Reflectance mean_value(const Pattern& pattern);

}  // namespace safegi::render
