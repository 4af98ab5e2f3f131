#include "safegi/cpu_renderer/procedural_texture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <concepts>
#include <limits>

#include "textures/noise.hpp"
#include "safegi/cpu_renderer/sampling.hpp"

namespace safegi::render {
namespace {

Reflectance rgb(Real r, Real g, Real b) { return sg::from_raw<Reflectance>(sg::vec3_rep(r, g, b)); }
Reflectance grey(Real value) { return rgb(value, value, value); }

// pbrt-v3's Spectrum::Clamp() on a texture's value: below 0 (and NaN) to 0,
// above 1 left as it is.
Reflectance non_negative(Reflectance value) {
  sg::vec3_rep v = sg::raw(value);
  for (int c = 0; c < 3; ++c) v[c] = std::isnan(v[c]) ? Real(0) : std::max(v[c], Real(0));
  return sg::from_raw<Reflectance>(v);
}

Reflectance mix(Real weight, Reflectance a, Reflectance b) { return (1 - weight) * a + weight * b; }

// Whether ⌊a⌋ + ⌊b⌋ + ⌊c⌋ is even, from each floor's parity (no int
// conversion, so any finite coordinate works; a not-finite one counts even).
bool even_cell(Real a, Real b, Real c = 0) {
  if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c)) return true;
  auto odd = [](Real x) { return std::abs(std::fmod(std::floor(x), Real(2))) == 1; };
  return (odd(a) + odd(b) + odd(c)) % 2 == 0;
}

// The share of [x − dx, x + dx] in odd columns [2k + 1, 2k + 2): the
// integral of their indicator (pbrt-v3's bumpInt) over the interval's length.
Real odd_share(Real x, Real dx) {
  if (!(dx > 0)) return even_cell(x, 0) ? Real(0) : Real(1);
  auto integral = [](Real y) {
    Real half = std::floor(y / 2);
    return half + 2 * std::max(y / 2 - half - Real(0.5), Real(0));
  };
  return (integral(x + dx) - integral(x - dx)) / (2 * dx);
}

Reflectance sample(const CheckerboardPattern& board, Real s, Real t, Real ds, Real dt) {
  const bool inside_one_check = std::floor(s - ds) == std::floor(s + ds) && std::floor(t - dt) == std::floor(t + dt);
  if (!board.box_filtered || inside_one_check) return even_cell(s, t) ? board.even : board.odd;
  // The box's share of odd checks: odd in s xor odd in t.
  const Real s_odd = odd_share(s, ds), t_odd = odd_share(t, dt);
  Real odd = s_odd + t_odd - 2 * s_odd * t_odd;
  if (ds == 1 || dt == 1) odd = 0.5f;  // pbrt-v3's, for a footprint of exactly one check
  return mix(odd, board.even, board.odd);
}

Reflectance sample(const DotsPattern& dots, Real s, Real t, Real, Real) {
  const Real s_cell = std::floor(s + Real(0.5)), t_cell = std::floor(t + Real(0.5));
  if (perlin_noise(s_cell + Real(0.5), t_cell + Real(0.5)) > 0) {
    constexpr Real radius = 0.35f, max_shift = 0.5f - radius;
    const Real s_centre = s_cell + max_shift * perlin_noise(s_cell + Real(1.5), t_cell + Real(2.8));
    const Real t_centre = t_cell + max_shift * perlin_noise(s_cell + Real(4.5), t_cell + Real(9.8));
    const Real ds = s - s_centre, dt = t - t_centre;
    if (ds * ds + dt * dt < radius * radius) return dots.inside;
  }
  return dots.outside;
}

Reflectance sample(const UvPattern&, Real s, Real t, Real, Real) { return rgb(s - std::floor(s), t - std::floor(t), 0); }

Reflectance sample(const BilerpPattern& bilerp, Real s, Real t, Real, Real) {
  return (1 - s) * (1 - t) * bilerp.v00 + (1 - s) * t * bilerp.v01 + s * (1 - t) * bilerp.v10 + s * t * bilerp.v11;
}

NoisePoint scaled(NoisePoint p, Real factor) { return {p.x * factor, p.y * factor, p.z * factor}; }

Reflectance sample(const SolidCheckerboardPattern& board, NoisePoint p, Real) {
  return even_cell(p.x, p.y, p.z) ? board.even : board.odd;
}

Reflectance sample(const FbmPattern& pattern, NoisePoint p, Real footprint) {
  return grey(pattern.turbulence ? turbulence(p, footprint, pattern.omega, pattern.octaves)
                                 : fbm(p, footprint, pattern.omega, pattern.octaves));
}

Reflectance sample(const WindyPattern&, NoisePoint p, Real footprint) {
  const Real wind = fbm(scaled(p, Real(0.1)), Real(0.1) * footprint, Real(0.5), 3);
  const Real waves = fbm(p, footprint, Real(0.5), 6);
  return grey(std::abs(wind) * waves);
}

// pbrt-v3's marble colours: the control points of six cubic Bézier segments.
constexpr std::array<std::array<float, 3>, 9> kMarbleColours = {{{.58f, .58f, .6f},
                                                                 {.58f, .58f, .6f},
                                                                 {.58f, .58f, .6f},
                                                                 {.5f, .5f, .5f},
                                                                 {.6f, .59f, .58f},
                                                                 {.58f, .58f, .6f},
                                                                 {.58f, .58f, .6f},
                                                                 {.2f, .2f, .33f},
                                                                 {.58f, .58f, .6f}}};
constexpr Real kMarbleGain = 1.5f;  // pbrt-v3's, "to increase variation among colors"

Reflectance marble_colour(int point) {
  const std::array<float, 3>& c = kMarbleColours[point];
  return rgb(c[0], c[1], c[2]);
}

Reflectance sample(const MarblePattern& marble, NoisePoint p, Real footprint) {
  p = scaled(p, marble.scale);
  const Real phase = p.y + marble.variation * fbm(p, marble.scale * footprint, marble.omega, marble.octaves);
  const Real t = Real(0.5) + Real(0.5) * std::sin(phase);
  constexpr int segments = static_cast<int>(kMarbleColours.size()) - 3;
  // pbrt-v3 picks the segment with min(1, ⌊6t⌋) where the segment t falls in
  // was meant, so for t ≥ 1/6 it extrapolates the second segment's cubic to
  // u = 6t − 1 ≤ 5, far beyond its hull (to about 40). That is what pbrt-v3's
  // marble scenes look like, so it is read as pbrt-v3 reads it; the importer
  // warns (docs/pbrt-import.md).
  const int first = std::min(1, static_cast<int>(std::floor(t * segments)));
  const Real u = t * segments - first;
  // De Casteljau on the segment's four control points.
  Reflectance a = mix(u, marble_colour(first), marble_colour(first + 1));
  Reflectance b = mix(u, marble_colour(first + 1), marble_colour(first + 2));
  Reflectance c = mix(u, marble_colour(first + 2), marble_colour(first + 3));
  a = mix(u, a, b);
  b = mix(u, b, c);
  return kMarbleGain * mix(u, a, b);
}

template <class P>
concept PlanarPattern = std::same_as<std::remove_cvref_t<decltype(P::mapping)>, Mapping2D>;
template <class P>
concept CompositePattern = std::same_as<P, MixPattern> || std::same_as<P, ProductPattern>;

Reflectance operand_value(const PatternOperand& operand, const PatternLookup& at) {
  return operand.pattern ? operand.value * evaluate_unclamped(operand.pattern->pattern, at) : operand.value;
}
Reflectance combine(const MixPattern& blend, const PatternLookup& at) {
  const Real amount = sg::raw(operand_value(blend.amount, at))[0];
  return mix(amount, operand_value(blend.first, at), operand_value(blend.second, at));
}
Reflectance combine(const ProductPattern& product, const PatternLookup& at) {
  return operand_value(product.first, at) * operand_value(product.second, at);
}
bool operand_reads_uv(const PatternOperand& operand) { return operand.pattern && reads_uv(operand.pattern->pattern); }
Reflectance operand_largest(const PatternOperand& operand) {
  return operand.pattern ? operand.value * largest_value(operand.pattern->pattern) : operand.value;
}
Reflectance operand_mean(const PatternOperand& operand) {
  return operand.pattern ? operand.value * mean_value(operand.pattern->pattern) : operand.value;
}

NoisePoint solid_point(const SolidMapping& mapping, PointWorld position) {
  const sg::vec3_rep v = mapping.coordinates(position);
  return {v.x, v.y, v.z};
}

Reflectance largest(Reflectance a, Reflectance b) {
  sg::vec3_rep x = sg::raw(a), y = sg::raw(b);
  return sg::from_raw<Reflectance>(glm::max(x, y));
}

// The patterns of given colours, and the largest value (per channel) each
// takes: its colours' (bilinear in [0, 1]² stays below its largest corner).
template <class P>
constexpr bool kColourPattern = std::is_same_v<P, CheckerboardPattern> || std::is_same_v<P, SolidCheckerboardPattern> ||
                                std::is_same_v<P, DotsPattern> || std::is_same_v<P, UvPattern> ||
                                std::is_same_v<P, BilerpPattern>;
template <class P>
Reflectance colour_bound(const P& p) {
  if constexpr (std::is_same_v<P, CheckerboardPattern> || std::is_same_v<P, SolidCheckerboardPattern>) {
    return largest(p.even, p.odd);
  } else if constexpr (std::is_same_v<P, DotsPattern>) {
    return largest(p.inside, p.outside);
  } else if constexpr (std::is_same_v<P, UvPattern>) {
    return rgb(1, 1, 0);
  } else {
    static_assert(std::is_same_v<P, BilerpPattern>);
    return largest(largest(p.v00, p.v01), largest(p.v10, p.v11));
  }
}

}  // namespace

sg::vec3_rep SolidMapping::coordinates(PointWorld position) const {
  const point<TextureSpace> origin = sg::from_raw<point<TextureSpace>>(sg::vec3_rep(0));
  return sg::raw((texture_from_render(position) - origin) / unit);
}

TextureCoordinates Mapping2D::at(Real u, Real v, PointWorld position) const {
  if (kind == Kind::uv) return {u * u_scale + u_offset, v * v_scale + v_offset};
  const sg::vec3_rep p = space.coordinates(position);
  if (kind == Kind::planar) return {u_offset + glm::dot(p, s_axis), v_offset + glm::dot(p, t_axis)};
  const Real length = glm::length(p);
  const sg::vec3_rep d = length > 0 ? p / length : sg::vec3_rep(0, 0, 1);
  if (kind == Kind::spherical) {
    Real phi = std::atan2(d.y, d.x);
    if (phi < 0) phi += 2 * kPi;
    return {std::acos(std::clamp(d.z, Real(-1), Real(1))) / kPi, phi / (2 * kPi)};
  }
  return {(kPi + std::atan2(d.y, d.x)) / (2 * kPi), d.z};
}

Real Mapping2D::uv_scale() const { return kind == Kind::uv ? std::max(std::abs(u_scale), std::abs(v_scale)) : Real(0); }

bool reads_uv(const Pattern& pattern) {
  return std::visit(
      [](const auto& p) {
        using P = std::remove_cvref_t<decltype(p)>;
        if constexpr (std::is_same_v<P, MixPattern>)
          return operand_reads_uv(p.first) || operand_reads_uv(p.second) || operand_reads_uv(p.amount);
        else if constexpr (std::is_same_v<P, ProductPattern>)
          return operand_reads_uv(p.first) || operand_reads_uv(p.second);
        else
          return PlanarPattern<P>;
      },
      pattern);
}

Reflectance evaluate(const Pattern& pattern, const PatternLookup& at) { return non_negative(evaluate_unclamped(pattern, at)); }

Real evaluate_number(const Pattern& pattern, const PatternLookup& at) { return sg::raw(evaluate_unclamped(pattern, at))[0]; }

Reflectance evaluate_unclamped(const Pattern& pattern, const PatternLookup& at) {
  return std::visit(
      [&](const auto& p) {
        if constexpr (CompositePattern<std::remove_cvref_t<decltype(p)>>) {
          return combine(p, at);
        } else if constexpr (PlanarPattern<std::remove_cvref_t<decltype(p)>>) {
          const Mapping2D& m = p.mapping;
          const TextureCoordinates st = m.at(at.u, at.v, at.position);
          if (m.kind != Mapping2D::Kind::uv) return sample(p, st.s, st.t, 0, 0);
          return sample(p, st.s, st.t, at.u_footprint * std::abs(m.u_scale), at.v_footprint * std::abs(m.v_scale));
        } else {
          const Real footprint = at.width * p.mapping.stretch / p.mapping.unit;
          return sample(p, solid_point(p.mapping, at.position), footprint);
        }
      },
      pattern);
}

Reflectance largest_value(const Pattern& pattern) {
  return std::visit(
      [](const auto& p) -> Reflectance {
        using P = std::remove_cvref_t<decltype(p)>;
        if constexpr (kColourPattern<P>) {
          return non_negative(colour_bound(p));
        } else if constexpr (std::is_same_v<P, MixPattern>) {  // an amount in [0, 1]: between the two
          return non_negative(largest(operand_largest(p.first), operand_largest(p.second)));
        } else if constexpr (std::is_same_v<P, ProductPattern>) {
          return non_negative(operand_largest(p.first) * operand_largest(p.second));
        } else {
          Reflectance found = grey(0);
          for (int i = 0; i < 16; ++i)
            for (int j = 0; j < 16; ++j)
              for (int k = 0; k < 16; ++k)
                found = largest(found, non_negative(sample(p, NoisePoint{i + Real(0.5), j + Real(0.5), k + Real(0.5)}, 0)));
          return found;
        }
      },
      pattern);
}

Reflectance mean_value(const Pattern& pattern) {
  // Point samples at the centres of a grid over many cells (64² of (s, t),
  // 16³ of texture space), unfiltered.
  return std::visit(
      [](const auto& p) -> Reflectance {
        Reflectance sum = grey(0);
        int count = 0;
        using P = std::remove_cvref_t<decltype(p)>;
        if constexpr (std::is_same_v<P, MixPattern>) {  // the parts taken as independent
          return non_negative(mix(sg::raw(operand_mean(p.amount))[0], operand_mean(p.first), operand_mean(p.second)));
        } else if constexpr (std::is_same_v<P, ProductPattern>) {
          return non_negative(operand_mean(p.first) * operand_mean(p.second));
        } else if constexpr (PlanarPattern<P>) {
          for (int i = 0; i < 128; ++i)
            for (int j = 0; j < 128; ++j, ++count) sum += non_negative(sample(p, (i + Real(0.5)) / 2, (j + Real(0.5)) / 2, 0, 0));
        } else {
          for (int i = 0; i < 32; ++i)
            for (int j = 0; j < 32; ++j)
              for (int k = 0; k < 32; ++k, ++count)
                sum += non_negative(sample(p, NoisePoint{(i + Real(0.5)) / 2, (j + Real(0.5)) / 2, (k + Real(0.5)) / 2}, 0));
        }
        return sum / static_cast<Real>(count);
      },
      pattern);
}

}  // namespace safegi::render
