// Run-time units for the scene loader: "5 mm", "60 deg", "17 W/(m2 sr)", "5 millimetre".
//
// Scene files name their units as text, so the loader needs a run-time twin of
// the compile-time dimensions: the compiler's dimension algebra over the same
// vocabulary, plus the factor that converts a value to the reference unit.
// Every conversion happens here, once, at load time (paper §3.3).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "safegi/dimension_algebra/dimension.hpp"
#include "safegi/dimension_algebra/registry.hpp"

namespace safegi::render {

// A scene value's dimension: the rendering vocabulary's (typed/include/safegi/typed/
// vocabulary.def, the one C++ and shaders use), over its bases length, time, energy, angle
// and solid_angle. The vocabulary's `proj` never appears in a scene file: it is the
// renderer's bookkeeping for the cosine factor, so scene dimensions leave it out.
using RuntimeDimension = ::safegi::Dimension;

// The vocabulary scene dimensions and units are named by (DimensionRegistry::rendering_prelude()).
const DimensionRegistry& scene_vocabulary();

// The dimensions scene fields are declared with, named as in the error messages.
namespace runtime_dim {
RuntimeDimension make(int length, int time, int energy, int angle, int solid_angle);
// The vocabulary's dimension of that name, without proj ("radiance" is W m^-2 sr^-1 here).
RuntimeDimension named(std::string_view vocabulary_name);
// `dimension` times base^exponent, for a base of the vocabulary (proj and others: unchanged).
RuntimeDimension with_base_power(const RuntimeDimension& dimension, std::string_view base, int exponent);
inline const RuntimeDimension none = {};
inline const RuntimeDimension length = named("length");
inline const RuntimeDimension time = named("time");
inline const RuntimeDimension angle = named("angle");
inline const RuntimeDimension power = named("power");
inline const RuntimeDimension intensity = named("intensity");
inline const RuntimeDimension radiance = named("radiance");
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

// Parses a unit expression: symbols or unit names (vocabulary.def: "mm" or
// "millimetre") with optional exponents ("m2", "m^2",
// "sr^-1"), products by space, '*' or '·', quotients by '/', parentheses.
// On failure returns nullopt and sets `error`.
std::optional<Unit> parse_unit(std::string_view text, std::string& error);

// Parses "<number> [unit expression]".
std::optional<Quantity> parse_quantity(std::string_view text, std::string& error);

}  // namespace safegi::render
