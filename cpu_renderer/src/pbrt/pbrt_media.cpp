// pbrt-v3 scene files, stage 3: participating media (pbrt-v3's core/api.cpp
// MakeMedium, GraphicsState::CreateMediumInterface and the integrators that
// trace them). Media are named anywhere; MediumInterface sets the graphics
// state's inside and outside media, which shapes take as they are made and
// the camera takes at WorldEnd (its outside one).
#include <algorithm>
#include <array>
#include <cmath>

#include "integrators/bdpt.hpp"
#include "pbrt/pbrt_importer.hpp"

namespace safegi::render::pbrt {

namespace {

// pbrt-v3's MakeMedium defaults (per scene unit): a thin, bluish haze.
constexpr Rgb kDefaultAbsorption{.0011, .0024, .014};
constexpr Rgb kDefaultScattering{2.55, 3.21, 3.77};

}  // namespace

void Importer::make_named_medium(const Directive& d) {
  const std::string& name = d.strings[0];
  ParamSet params(d.params, "MakeNamedMedium \"" + name + "\"");
  const Param* type_param = params.find("type", {ParamType::string});
  if (!type_param)
    fail(d.string_ranges[0], "MakeNamedMedium \"" + name + "\" has no \"string type\"", "pbrt-v3 has \"homogeneous\" and \"heterogeneous\"");
  const std::string type = params.one_string("type", "");
  if (type == "heterogeneous")
    params.fail_at(*type_param, "a heterogeneous medium (a density grid) is not supported", "supported: \"homogeneous\"");
  if (type != "homogeneous")
    params.fail_at(*type_param, "unknown medium type \"" + type + "\"", "pbrt-v3 has \"homogeneous\" and \"heterogeneous\"");
  params.reject("preset", "give \"sigma_a\" and \"sigma_s\" instead: pbrt-v3's table of measured media is not here");
  const double scale = params.one_float("scale", 1);
  const Param* scale_param = params.find("scale", {ParamType::floating});
  if (!(scale >= 0))
    params.fail_at(*scale_param, "\"scale\" of " + params.context() + " must not be negative, found " + format_number(scale));
  const double g = params.one_float("g", 0);
  if (!(g > -1 && g < 1))
    params.fail_at(*params.find("g", {ParamType::floating}),
                   "\"g\" of " + params.context() + " must lie in (-1, 1), found " + format_number(g),
                   "Henyey-Greenstein's asymmetry: 0 scatters evenly, towards 1 forwards, towards -1 backwards");
  Medium medium;
  medium.name = name;
  medium.asymmetry = static_cast<Real>(g);
  medium.absorption = coefficients(params, "sigma_a", kDefaultAbsorption, scale, scale_param);
  medium.scattering = coefficients(params, "sigma_s", kDefaultScattering, scale, scale_param);
  report_unused(params);
  // pbrt-v3 replaces a medium of the same name; shapes made before keep the old one.
  named_media_[name] = static_cast<int>(result_.scene.media.size());
  result_.scene.media.push_back(std::move(medium));
}

// σa or σs: per scene unit in the file, per metre here.
spectrum<dim::inv_length> Importer::coefficients(ParamSet& params, const char* name, const Rgb& fallback, double scale,
                                                 const Param* scale_param) {
  std::optional<SpectrumValue> given = params.spectrum(name, false);
  const Rgb rgb = given ? given->rgb : fallback;
  std::array<quantity<dim::inv_length>, 3> per_metre;
  for (int c = 0; c < 3; ++c) {
    if (!(rgb[c] >= 0))
      params.fail_at(*given->param, "\"" + std::string(name) + "\" of " + params.context() +
                                        " must not be negative, found " + format_number(rgb[c]) + " in a channel");
    const Real value = static_cast<Real>(rgb[c] * scale / options_.metres_per_unit);
    if (!std::isfinite(value))
      params.fail_at(given ? *given->param : *scale_param,
                     "\"" + std::string(name) + "\" of " + params.context() + " times \"scale\" is out of " + kRealName +
                         " range per metre");
    per_metre[c] = sg::from_raw<quantity<dim::inv_length>>(value);
  }
  return {per_metre[0], per_metre[1], per_metre[2]};
}

void Importer::medium_interface(const Directive& d) {
  // One name is both sides (pbrt-v3's parser repeats it).
  const size_t outside = d.strings.size() > 1 ? 1 : 0;
  state_.inside_medium = {d.strings[0], d.string_ranges[0]};
  state_.outside_medium = {d.strings[outside], d.string_ranges[outside]};
}

// The index of the medium a MediumInterface named; -1 for "" (vacuum).
int Importer::medium_index(const NamedMedium& medium) {
  if (medium.name.empty()) return -1;
  auto found = named_media_.find(medium.name);
  if (found == named_media_.end())
    fail(medium.at, "no medium named \"" + medium.name + "\"", "MakeNamedMedium defines one, before the shapes that use it");
  media_used_ = true;
  return found->second;
}

// The media a shape made now bounds, if they differ (pbrt-v3: a transition).
std::optional<MediumInterface> Importer::shape_media() {
  MediumInterface media{medium_index(state_.inside_medium), medium_index(state_.outside_medium)};
  if (media.inside == media.outside) return std::nullopt;
  return media;
}

// At WorldEnd: the camera's medium, and pbrt-v3's rule that only volpath, bdpt
// and mlt trace media; under any other integrator it renders without them, a
// boundary with no surface is nothing, and so do we (with a warning, as pbrt-v3).
void Importer::finish_media(SourceRange world_end) {
  Scene& scene = result_.scene;
  scene.camera.medium = medium_index(state_.outside_medium);
  // Those integrators' shadow rays stop at any surface, one of material "none" too
  // (pbrt-v3's VisibilityTester::Unoccluded); volpath's, bdpt's and mlt's pass through it.
  if (!integrator_traces_media_)
    for (Shape& shape : scene.shapes) shape.occludes_light = shape.invisible;
  fall_back_from_bdpt(world_end);
  if (!media_used_ || integrator_traces_media_) return;
  warn(integrator_at_ ? *integrator_at_ : world_end,
       "the scene has participating media, which pbrt-v3's integrator \"" + integrator_name_ +
           "\" does not trace: rendering without them, as pbrt-v3 does",
       "\"volpath\", \"bdpt\" or \"mlt\" render them (here: the path tracer, which traces them)");
  scene.drop_media();
}

// bdpt (and mlt, rendered by it) where ours cannot render the scene (media,
// the environment, distant lights, a thin lens, diffuse transmission): the
// path tracer, with a warning that says what it misses.
void Importer::fall_back_from_bdpt(SourceRange world_end) {
  Scene& scene = result_.scene;
  if (scene.settings.integrator != IntegratorType::bdpt) return;
  const std::optional<std::string> reason = bdpt_refusal(scene);
  if (!reason) return;
  scene.settings.integrator = IntegratorType::path;
  warn(integrator_at_ ? *integrator_at_ : world_end,
       "integrator \"" + integrator_name_ + "\": bdpt cannot render this scene (" + *reason +
           "): rendering with \"path\"",
       "the same image in expectation except caustics of point and spot lights seen through specular surfaces, "
       "which the path tracer cannot sample");
}

}  // namespace safegi::render::pbrt
