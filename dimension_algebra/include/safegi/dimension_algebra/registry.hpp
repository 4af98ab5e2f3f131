#pragma once
// The vocabulary a program declares: base dimensions, derived dimension names,
// units (a dimension and a scale to the reference unit) and coordinate spaces.
// It prints dimensions in the user's own words.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "safegi/dimension_algebra/dimension.hpp"

namespace safegi {

using SpaceId = std::uint32_t;

struct DerivedDimension {
  std::string name;
  Dimension value;
};

struct Unit {
  std::string name;
  Dimension dimension;
  double scale = 1.0;  // value in the reference unit of one of this unit
};

enum class Notation { unicode, ascii };

// A rational exponent, used to describe non-integer unification results.
struct RationalFactor {
  BaseId base = 0;
  std::int64_t numerator = 0;
  std::int64_t denominator = 1;
};

// A base dimension of quantities SI measures as plain numbers (an angle is a ratio of
// lengths): `dimension angle : ratio;`. Kept apart from other bases all the same, but a
// cast may change ratio bases and nothing else (docs/language.md, "Casts").
enum class BaseKind { physical, ratio };

class DimensionRegistry {
 public:
  // The rendering prelude, the same vocabulary as safegi/prelude.sgl (see
  // docs/language.md): bases length, time, energy, angle, solid_angle, proj;
  // derived dimensionless, area, volume, velocity, power, intensity, irradiance,
  // radiant_exitance, radiance, brdf, pdfs per solid angle / projected solid
  // angle / area / length, inv_length, inv_area; units meter … steradian.
  // It declares no spaces: a program declares its own.
  static DimensionRegistry rendering_prelude();

  // Each add_* returns nothing (and changes nothing) when the name is already
  // declared in any namespace of the registry; the caller reports the clash.
  std::optional<BaseId> add_base(std::string name, BaseKind kind = BaseKind::physical);
  bool add_derived(std::string name, Dimension value);
  bool add_unit(std::string name, Dimension dimension, double scale);
  // eye: the space's origin is the eye (`space view : eye;`), so a point's coordinates are the
  // vector from the eye to it.
  // frame: a local frame whose z axis is the surface normal (`space shading : frame;`), so a
  // direction's z coordinate is its cosine to the normal.
  std::optional<SpaceId> add_space(std::string name, bool eye = false, bool frame = false);
  bool is_eye_space(SpaceId id) const { return id < eye_spaces_.size() && eye_spaces_[id]; }
  bool is_frame_space(SpaceId id) const { return id < frame_spaces_.size() && frame_spaces_[id]; }

  bool is_declared(std::string_view name) const { return kinds_.count(std::string(name)) != 0; }
  std::optional<BaseId> find_base(std::string_view name) const;
  const DerivedDimension* find_derived(std::string_view name) const;
  // A base or derived dimension name.
  std::optional<Dimension> find_dimension(std::string_view name) const;
  const Unit* find_unit(std::string_view name) const;
  std::optional<SpaceId> find_space(std::string_view name) const;

  std::size_t base_count() const { return bases_.size(); }
  // A ratio base, or a unit factor of a unit of ratio bases (degree).
  bool is_ratio_base(BaseId id) const;
  // Every factor of `d` a ratio base: a cast may multiply by it.
  bool is_only_ratios(const Dimension& d) const;
  const std::string& base_name(BaseId id) const { return bases_.at(id); }

  // Units as factors of a dimension (docs/language.md, "Units"). A value of
  // `length in centimeter` has the dimension centimeter¹, where centimeter is a
  // *unit factor* (id kUnitBase + the index of the first unit declared with the
  // same dimension and scale), so the Abelian-group algebra, unification and
  // equality carry units unchanged: centimeter·centimeter = centimeter², and
  // centimeter ≠ length. A unit of scale 1 is the reference unit: its factor is
  // its dimension (`length in meter` is `length`).
  static constexpr BaseId kUnitBase = 1u << 20;
  // The shortest decimal text that reads back as `value`, fixed-point where that
  // is short ("0.01", "100.0", "0.017453292519943295"), else with an exponent:
  // a valid GLSL float literal.
  static std::string format_number(double value);
  // Scales equal up to rounding (a relative 1e-12): `12.0 * inch` is `foot`.
  static bool same_scale(double a, double b);
  // The dimension of one `unit`: its unit factor, or its dimension when its scale is 1.
  Dimension measured_in(const Unit& unit) const;
  bool is_unit_factor(BaseId id) const { return id >= kUnitBase && id - kUnitBase < units_.size(); }
  const Unit& unit_of_factor(BaseId id) const { return units_.at(id - kUnitBase); }
  bool has_unit_factors(const Dimension& d) const;
  // Unit factors replaced by their units' dimensions: what `d` measures.
  Checked<Dimension> reference(const Dimension& d) const;
  // How many reference units one unit of `d` is: the product of its unit factors' scales.
  double scale(const Dimension& d) const;
  // A base name, or the unit name of a unit factor ("?" for an unknown id).
  std::string factor_name(BaseId id) const;
  // `d` spelled in units: unit factors by name, reference bases by the name of
  // their scale-1 unit when one exists (`centimeter·second⁻¹`), else by base name.
  std::string format_units(const Dimension& d, Notation notation = Notation::unicode) const;
  const std::string& space_name(SpaceId id) const { return spaces_.at(id); }
  const std::vector<std::string>& bases() const { return bases_; }
  const std::vector<DerivedDimension>& derived() const { return derived_; }
  const std::vector<Unit>& units() const { return units_; }
  const std::vector<std::string>& spaces() const { return spaces_; }

  // Builds a dimension from (name, exponent) pairs of base or derived names;
  // nothing if a name is unknown or the exponents overflow.
  std::optional<Dimension> make(std::initializer_list<std::pair<std::string_view, std::int32_t>> terms) const;

  // The first-declared derived name equal to d; else a base name; else the
  // normalised product: positive exponents first, then negative, each group in
  // base declaration order (`energy·length⁻²`, ASCII `energy*length^-2`).
  // The dimensionless dimension prints as `1` unless a derived name (`dimensionless`) matches.
  // A dimension with unit factors prints as what it measures and its units:
  // `length in centimeter`, `area in centimeter²`.
  std::string format(const Dimension& d, Notation notation = Notation::unicode) const;
  // Always the normalised product of bases, never a derived name.
  std::string format_product(const Dimension& d, Notation notation = Notation::unicode) const;
  // In SI units, for people: the prelude's bases as m, s, J, rad and sr,
  // J·s⁻¹ combined into W, positive exponents first (`W·m⁻²·sr⁻¹` for
  // radiance, ASCII `W*m^-2*sr^-1`); a base without an SI symbol (a program's
  // own `pixel`) keeps its name; nothing left prints as `1`. `proj` is left
  // out: the projected-cosine factor is a ratio of lengths, a pure number in
  // SI, and radiometry writes radiance per projected solid angle as
  // W·m⁻²·sr⁻¹. The checker keeps proj (format_product shows it); these
  // words are what a reader compares with a textbook. A dimension with unit
  // factors is spelled in its own units (format_units).
  std::string format_si(const Dimension& d, Notation notation = Notation::unicode) const;
  std::string format_rational(const std::vector<RationalFactor>& factors, Notation notation = Notation::unicode) const;
  std::string describe(const DimensionError& error) const;

 private:
  enum class Kind { base, derived, unit, space };
  std::string format_factors(const std::vector<RationalFactor>& factors, Notation notation,
                             const std::function<std::string(BaseId)>& name_of) const;
  bool claim(const std::string& name, Kind kind);

  std::vector<std::string> bases_;
  std::vector<bool> ratio_bases_;  // per base: BaseKind::ratio
  std::vector<DerivedDimension> derived_;
  std::vector<Unit> units_;
  std::vector<std::string> spaces_;
  std::vector<bool> eye_spaces_;    // per space: its origin is the eye
  std::vector<bool> frame_spaces_;  // per space: its z axis is the surface normal
  std::unordered_map<std::string, std::pair<Kind, std::size_t>> kinds_;
};

}  // namespace safegi
