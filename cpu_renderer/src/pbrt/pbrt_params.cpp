#include "pbrt/pbrt_params.hpp"

#include "pbrt/pbrt_colour.hpp"
#include "safegi/cpu_renderer/quoted_list.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace safegi::render::pbrt {

namespace {

std::string type_names(std::initializer_list<ParamType> types) {
  std::vector<std::string_view> names;
  for (ParamType type : types) names.push_back(param_type_name(type));
  return quoted_list(names);
}

std::string declared(const Param& param) { return "\"" + param.type_name + " " + param.name + "\""; }

}  // namespace

ParamSet::ParamSet(const std::vector<Param>& params, std::string context, ParamSet* fallback)
    : context_(std::move(context)), fallback_(fallback) {
  for (const Param& param : params) params_.push_back(&param);
  used_.assign(params_.size(), false);
}

void ParamSet::fail_at(const Param& param, const std::string& message, const std::string& hint) const {
  fail(param.declaration, message, hint);
}

bool ParamSet::contains(std::string_view name) const {
  for (const Param* param : params_)
    if (param->name == name) return true;
  return false;
}

const Param* ParamSet::find(std::string_view name, std::initializer_list<ParamType> types) {
  // As in pbrt-v3, a later parameter of the same name replaces an earlier one.
  for (size_t i = params_.size(); i-- > 0;) {
    const Param& param = *params_[i];
    if (param.name != name) continue;
    for (size_t j = 0; j < params_.size(); ++j)
      if (params_[j]->name == name) used_[j] = true;
    bool allowed = false;
    for (ParamType type : types) allowed = allowed || param.type == type;
    if (!allowed)
      fail_at(param, context_ + " reads \"" + std::string(name) + "\" as " + type_names(types) + ", found " +
                         declared(param),
              "pbrt-v3 would ignore this parameter and use its default; write the type it expects");
    return &param;
  }
  return fallback_ ? fallback_->find(name, types) : nullptr;
}

const Param* ParamSet::single(std::string_view name, std::initializer_list<ParamType> types, size_t values) {
  const Param* param = find(name, types);
  if (!param) return nullptr;
  size_t count = param->is_string ? param->strings.size() : param->numbers.size();
  if (count != values)
    fail(param->values, declared(*param) + " of " + context_ + " takes " + std::to_string(values) + " value" +
                            (values == 1 ? "" : "s") + ", found " + std::to_string(count));
  return param;
}

double ParamSet::one_float(std::string_view name, double fallback) {
  const Param* param = single(name, {ParamType::floating}, 1);
  return param ? param->numbers[0] : fallback;
}

int ParamSet::one_int(std::string_view name, int fallback, int minimum, int maximum) {
  const Param* param = single(name, {ParamType::integer}, 1);
  if (!param) return fallback;
  double value = param->numbers[0];
  if (value != std::floor(value) || value < minimum || value > maximum)
    fail(param->values, declared(*param) + " of " + context_ + " must be an integer in [" + std::to_string(minimum) +
                            ", " + std::to_string(maximum) + "]");
  return static_cast<int>(value);
}

bool ParamSet::one_bool(std::string_view name, bool fallback) {
  const Param* param = single(name, {ParamType::boolean}, 1);
  return param ? param->strings[0] == "true" : fallback;
}

std::string ParamSet::one_string(std::string_view name, const std::string& fallback) {
  const Param* param = single(name, {ParamType::string}, 1);
  return param ? param->strings[0] : fallback;
}

std::optional<Triple> ParamSet::one_point(std::string_view name) {
  const Param* param = single(name, {ParamType::point3}, 3);
  if (!param) return std::nullopt;
  return Triple{param->numbers[0], param->numbers[1], param->numbers[2]};
}

std::optional<Triple> ParamSet::one_vector(std::string_view name) {
  const Param* param = single(name, {ParamType::vector3}, 3);
  if (!param) return std::nullopt;
  return Triple{param->numbers[0], param->numbers[1], param->numbers[2]};
}

std::vector<double> ParamSet::floats(std::string_view name) {
  const Param* param = find(name, {ParamType::floating});
  return param ? param->numbers : std::vector<double>{};
}

std::optional<SpectrumValue> ParamSet::spectrum(std::string_view name, bool allow_texture) {
  const Param* param =
      allow_texture ? find(name, {ParamType::rgb, ParamType::xyz, ParamType::blackbody, ParamType::spectrum,
                                  ParamType::texture})
                    : find(name, {ParamType::rgb, ParamType::xyz, ParamType::blackbody, ParamType::spectrum});
  if (!param) return std::nullopt;
  SpectrumValue value;
  value.param = param;
  if (param->type == ParamType::texture) {
    if (param->strings.size() != 1)
      fail(param->values, declared(*param) + " names one texture, found " + std::to_string(param->strings.size()));
    value.texture = param->strings[0];
    return value;
  }
  const std::vector<double>& v = param->numbers;
  if (param->type == ParamType::spectrum) {
    value.rgb = sampled_spectrum(*param);
    return value;
  }
  if (param->type == ParamType::blackbody) {
    // pbrt-v3 reads [temperature scale]; pbrt-v4's one value is another format.
    if (v.size() != 2)
      fail(param->values, declared(*param) + " takes [temperature scale] (2 values, pbrt-v3), found " +
                              std::to_string(v.size()));
    if (!(v[0] > 0)) fail(param->values, declared(*param) + ": the temperature (kelvin) must be above 0");
    value.rgb = normalized_blackbody_rgb(v[0]);
    for (double& c : value.rgb) c *= v[1];
    return value;
  }
  if (v.size() != 3)
    fail(param->values, declared(*param) + " takes 3 values, found " + std::to_string(v.size()));
  value.rgb = param->type == ParamType::xyz ? xyz_to_rgb({v[0], v[1], v[2]}) : Rgb{v[0], v[1], v[2]};
  return value;
}

// pbrt-v3 reads "spectrum" as [wavelength value ...] pairs, or as the name of
// a file of such pairs (which the parser has read into `numbers`). A name is
// one of pbrt-v4's measured metals, which scenes exported for pbrt-v4 use.
Rgb ParamSet::sampled_spectrum(const Param& param) const {
  if (param.is_string) {
    std::optional<Rgb> named = param.strings.size() == 1 ? named_spectrum_rgb(param.strings[0]) : std::nullopt;
    if (!named)
      fail(param.values, declared(param) + " names one spectrum or file, found " + std::to_string(param.strings.size()));
    return *named;
  }
  const std::vector<double>& v = param.numbers;
  if (v.empty() || v.size() % 2 != 0)
    fail(param.values, declared(param) + " takes [wavelength value ...] pairs, found " + std::to_string(v.size()) +
                           " number" + (v.size() == 1 ? "" : "s"));
  std::vector<SpectrumSample> samples;
  for (size_t i = 0; i < v.size(); i += 2) {
    if (!(v[i] > 0)) fail(param.values, declared(param) + ": wavelengths (nm) must be above 0, found " + format_number(v[i]));
    samples.push_back({v[i], v[i + 1]});
  }
  // Sorted first, so that a long list is checked in n log n.
  std::sort(samples.begin(), samples.end(),
            [](const SpectrumSample& a, const SpectrumSample& b) { return a.wavelength_nm < b.wavelength_nm; });
  for (size_t i = 1; i < samples.size(); ++i)
    if (samples[i].wavelength_nm == samples[i - 1].wavelength_nm)
      fail(param.values, declared(param) + " gives the wavelength " + format_number(samples[i].wavelength_nm) + " nm twice",
           "pbrt-v3 stops on a failed check there");
  return sampled_spectrum_rgb(std::move(samples));
}

void ParamSet::reject(std::string_view name, const std::string& why, std::optional<double> harmless) {
  const Param* last = nullptr;
  for (size_t i = 0; i < params_.size(); ++i) {
    if (params_[i]->name != name) continue;
    used_[i] = true;
    last = params_[i];
  }
  if (!last) {
    if (fallback_) fallback_->reject(name, why, harmless);
    return;
  }
  if (harmless && last->type == ParamType::floating && last->numbers.size() == 1 && last->numbers[0] == *harmless)
    return;
  fail_at(*last, declared(*last) + " of " + context_ + " is not supported: " + why);
}

std::vector<const Param*> ParamSet::unused() const {
  std::vector<const Param*> result;
  for (size_t i = 0; i < params_.size(); ++i)
    if (!used_[i]) result.push_back(params_[i]);
  return result;
}

void ParamSet::ignore_the_rest() { used_.assign(used_.size(), true); }

std::string format_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace safegi::render::pbrt
