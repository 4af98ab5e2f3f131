// Run-time units for the scene loader: "5 mm", "60 deg", "17 W/(m2 sr)".
//
// Scene files name their units as text, so the loader needs a run-time twin of
// the compile-time dimensions: an exponent vector over the user-visible base
// dimensions plus the factor that converts a value to the reference unit.
// Every conversion happens here, once, at load time (paper §3.3).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace safegi::render {

// Base dimensions a scene author can write. The renderer's internal `proj`
// base never appears in a scene file: it is bookkeeping for the cosine factor.
enum class Base : int { length, time, energy, angle, solid_angle, count };

struct RuntimeDimension {
  std::array<int, static_cast<int>(Base::count)> exponents{};

  friend bool operator==(const RuntimeDimension&, const RuntimeDimension&) = default;
  RuntimeDimension operator*(const RuntimeDimension& other) const;
  RuntimeDimension inverse() const;
  RuntimeDimension pow(int power) const;
  bool dimensionless() const { return *this == RuntimeDimension{}; }
};

// The dimensions scene fields are declared with, named as in the error messages.
namespace runtime_dim {
RuntimeDimension make(int length, int time, int energy, int angle, int solid_angle);
inline const RuntimeDimension none = {};
inline const RuntimeDimension length = make(1, 0, 0, 0, 0);
inline const RuntimeDimension time = make(0, 1, 0, 0, 0);
inline const RuntimeDimension angle = make(0, 0, 0, 1, 0);
inline const RuntimeDimension power = make(0, -1, 1, 0, 0);
inline const RuntimeDimension intensity = make(0, -1, 1, 0, -1);
inline const RuntimeDimension radiance = make(-2, -1, 1, 0, -1);
}  // namespace runtime_dim

// "power (e.g. W)" for a known dimension, else its base-unit spelling "m^2 s^-1".
std::string describe(const RuntimeDimension& dimension);
// Only the name: "power", "length", or the base-unit spelling.
std::string dimension_name(const RuntimeDimension& dimension);

struct Unit {
  double to_reference = 1.0;  // value in this unit × to_reference = value in reference units
  RuntimeDimension dimension;
};

struct Quantity {
  double value = 0.0;  // already in reference units (m, s, J, rad, sr)
  RuntimeDimension dimension;
};

// Parses a unit expression: symbols with optional exponents ("m2", "m^2",
// "sr^-1"), products by space, '*' or '·', quotients by '/', parentheses.
// On failure returns nullopt and sets `error`.
std::optional<Unit> parse_unit(std::string_view text, std::string& error);

// Parses "<number> [unit expression]".
std::optional<Quantity> parse_quantity(std::string_view text, std::string& error);

}  // namespace safegi::render
