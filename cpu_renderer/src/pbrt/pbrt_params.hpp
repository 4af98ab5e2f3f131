// Typed lookups in a pbrt-v3 parameter list, with pbrt-v3's defaults given by
// the caller. Stricter than pbrt-v3 where it would silently ignore a value:
// a parameter of the wrong type or with the wrong number of values is an
// error naming both; a parameter nobody looked up is reported as unused.
#pragma once

#include <array>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pbrt/pbrt_parser.hpp"

namespace safegi::render::pbrt {

using Rgb = std::array<double, 3>;
using Triple = std::array<double, 3>;

// A spectrum parameter: a value, or the name of a texture ("texture Kd").
struct SpectrumValue {
  Rgb rgb{};
  std::string texture;  // non-empty: a texture name
  const Param* param = nullptr;
};

class ParamSet {
 public:
  // `context` names the directive in messages: `Shape "sphere"`. `fallback`
  // is searched after this list (a shape's parameters override its material's).
  ParamSet(const std::vector<Param>& params, std::string context, ParamSet* fallback = nullptr);

  // The parameter called `name`, or nullptr; marks it used. Present with a
  // type outside `types` is an error naming what was expected.
  const Param* find(std::string_view name, std::initializer_list<ParamType> types);

  double one_float(std::string_view name, double fallback);
  int one_int(std::string_view name, int fallback, int minimum, int maximum);
  bool one_bool(std::string_view name, bool fallback);
  std::string one_string(std::string_view name, const std::string& fallback);
  std::optional<Triple> one_point(std::string_view name);
  std::optional<Triple> one_vector(std::string_view name);
  std::vector<double> floats(std::string_view name);              // every value, any count
  // rgb/color, xyz, blackbody [temperature scale] and spectrum ([wavelength
  // value ...] pairs, or one of pbrt-v4's named metal spectra), converted as
  // pbrt-v3's RGB build converts them, or a texture name where `allow_texture`.
  std::optional<SpectrumValue> spectrum(std::string_view name, bool allow_texture);

  // A parameter pbrt-v3 reads but the importer cannot represent: an error,
  // unless it holds `harmless` (e.g. "float sigma" [0]).
  void reject(std::string_view name, const std::string& why, std::optional<double> harmless = std::nullopt);

  // Parameters nobody looked up (pbrt-v3 would ignore them too).
  std::vector<const Param*> unused() const;
  // Every parameter counted as used: for a directive that makes nothing, whose
  // other parameters nothing reads.
  void ignore_the_rest();
  const std::string& context() const { return context_; }
  void set_fallback(ParamSet* fallback) { fallback_ = fallback; }
  bool contains(std::string_view name) const;

  [[noreturn]] void fail_at(const Param& param, const std::string& message, const std::string& hint = {}) const;

 private:
  const Param* single(std::string_view name, std::initializer_list<ParamType> types, size_t values);
  Rgb sampled_spectrum(const Param& param) const;

  std::vector<const Param*> params_;
  std::vector<bool> used_;
  std::string context_;
  ParamSet* fallback_;
};

// A number as messages quote it (%g).
std::string format_number(double value);

}  // namespace safegi::render::pbrt
