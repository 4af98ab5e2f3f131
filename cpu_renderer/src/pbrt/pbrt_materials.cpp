// The importer's materials and textures: pbrt-v3's matte, mirror, plastic,
// glass, metal, substrate, translucent, disney (pbrt_disney.cpp) and the
// matte/plastic/glass subsets of uber (src/materials/*.cpp), and
// its constant, imagemap and scale textures (src/textures/*.cpp), mapped onto
// the Scene's materials and image textures. What the Scene cannot represent
// is an error at the parameter or name that asks for it.
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>

#include "pbrt/pbrt_colour.hpp"
#include "pbrt/pbrt_importer.hpp"

namespace safegi::render::pbrt {

namespace {

template <class M>
M& writable(std::shared_ptr<M>& shared) {
  if (shared.use_count() > 1) shared = std::make_shared<M>(*shared);
  return *shared;
}

// The parameters each supported material reads: a shape that carries one of
// them gets its own copy of the material (pbrt-v3's GetMaterialForShape).
struct MaterialParams {
  std::string_view type;
  std::array<std::string_view, 16> names;  // empty names pad the list
};
constexpr MaterialParams kMaterialParams[] = {
    {"matte", {"Kd", "sigma", "bumpmap"}},
    {"mirror", {"Kr", "bumpmap"}},
    {"plastic", {"Kd", "Ks", "roughness", "remaproughness", "bumpmap"}},
    {"glass", {"Kr", "Kt", "eta", "index", "uroughness", "vroughness", "remaproughness", "bumpmap"}},
    {"metal", {"eta", "k", "roughness", "uroughness", "vroughness", "remaproughness", "bumpmap"}},
    {"substrate", {"Kd", "Ks", "uroughness", "vroughness", "remaproughness", "bumpmap"}},
    {"translucent", {"Kd", "Ks", "reflect", "transmit", "roughness", "remaproughness", "bumpmap"}},
    {"uber",
     {"Kd", "Ks", "Kr", "Kt", "roughness", "uroughness", "vroughness", "eta", "index", "opacity", "remaproughness",
      "bumpmap"}},
    {"mix", {"amount", "namedmaterial1", "namedmaterial2"}},
    {"disney",
     {"color", "metallic", "eta", "roughness", "speculartint", "anisotropic", "sheen", "sheentint", "clearcoat",
      "clearcoatgloss", "spectrans", "scatterdistance", "thin", "flatness", "difftrans", "bumpmap"}},
};
constexpr const char* kSupportedMaterials =
    "supported: \"matte\", \"mirror\", \"plastic\", \"glass\", \"metal\", \"substrate\", \"translucent\", "
    "\"uber\", \"mix\", \"disney\"";
constexpr const char* kSupportedTextures =
    "supported: \"constant\", \"imagemap\", \"scale\", \"mix\", \"checkerboard\", \"dots\", \"fbm\", "
    "\"wrinkled\", \"windy\", \"marble\", \"uv\", \"bilerp\"";

bool reads_material_params(const std::string& type, const ParamSet& shape) {
  for (const MaterialParams& m : kMaterialParams)
    if (m.type == type)
      for (std::string_view name : m.names)
        if (!name.empty() && shape.contains(name)) return true;
  return false;
}

bool black(const TexturedReflectance& r) { return sg::is_black(r.value); }

// A texture a material reads: its deferred error is reported now.
const TextureEntry& usable(const TextureEntry& texture) {
  if (texture.error) throw PbrtError(*texture.error);
  return texture;
}

// A material that absorbs everything: pbrt-v3's black matte, as no material at all.
bool absorbs_everything(const Material& material) {
  return !material.mix && std::holds_alternative<BlackMaterial>(material.model);
}

MaterialModel lambert_or_black(const TexturedReflectance& kd) {
  if (black(kd)) return BlackMaterial{};  // absorbs, as pbrt-v3's black matte does
  return LambertMaterial{kd};
}

std::string lower_extension(const std::string& file) {
  std::string extension = std::filesystem::path(file).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  return extension;
}

// A parameter that names an image texture or a pattern where the material
// reads a constant.
[[noreturn]] void refuse_texture(const ParamSet& params, const Param& param, const TextureEntry& texture,
                                 std::string_view name, const std::string& hint) {
  const char* kind = texture.image >= 0 ? "an image texture" : "a procedural texture";
  params.fail_at(param, std::string(kind) + " as \"" + std::string(name) + "\" of " + params.context() + " is not supported",
                 hint);
}

std::string format_rgb(const Rgb& rgb) {
  std::string text;
  for (double channel : rgb) {
    text += text.empty() ? "[" : " ";
    text += format_number(channel);
  }
  return text + "]";
}

// pbrt-v3's TrowbridgeReitzDistribution::RoughnessToAlpha.
double roughness_to_alpha(double roughness) {
  double x = std::log(std::max(roughness, 1e-3));
  return 1.62142 + 0.819955 * x + 0.1734 * x * x + 0.0171201 * x * x * x + 0.000640711 * x * x * x * x;
}

// A microfacet alpha as pbrt-v3 computes it: remapped from a perceptual
// roughness (RoughnessToAlpha) or taken as given, then clamped to 0.001 as its
// TrowbridgeReitzDistribution does.
double microfacet_alpha(double roughness, bool remap) {
  return std::max(1e-3, remap ? roughness_to_alpha(roughness) : roughness);
}

}  // namespace

// ---------------------------------------------------------------------------
// Parameter values: numbers, colours and the textures they name

std::optional<TextureEntry> Importer::spectrum_or_texture(ParamSet& params, const char* name, const Param*& param) {
  std::optional<SpectrumValue> value = params.spectrum(name, true);
  if (!value) return std::nullopt;
  param = value->param;
  if (value->texture.empty()) {
    TextureEntry entry;
    entry.value = value->rgb;
    return entry;
  }
  auto found = state_.spectrum_textures->find(value->texture);
  if (found == state_.spectrum_textures->end())
    fail(value->param->values, "no spectrum texture named \"" + value->texture + "\"",
         "Texture \"" + value->texture + "\" \"spectrum\" ... defines one");
  return usable(found->second);
}

// A float parameter: a number, or a float texture (a constant, or a constant
// times an image).
std::optional<TextureEntry> Importer::float_or_texture(ParamSet& params, const char* name, const Param*& param) {
  param = params.find(name, {ParamType::floating, ParamType::texture});
  if (!param) return std::nullopt;
  size_t count = param->is_string ? param->strings.size() : param->numbers.size();
  if (count != 1)
    fail(param->values, "\"" + param->type_name + " " + param->name + "\" of " + params.context() + " takes 1 value, found " +
                            std::to_string(count));
  if (param->type == ParamType::floating) {
    TextureEntry entry;
    entry.value = {param->numbers[0], param->numbers[0], param->numbers[0]};
    return entry;
  }
  auto found = state_.float_textures->find(param->strings[0]);
  if (found == state_.float_textures->end())
    fail(param->values, "no float texture named \"" + param->strings[0] + "\"",
         "Texture \"" + param->strings[0] + "\" \"float\" ... defines one");
  return usable(found->second);
}

// A float parameter the renderer reads as a constant.
std::optional<double> Importer::float_param(ParamSet& params, const char* name) {
  const Param* param = nullptr;
  std::optional<TextureEntry> entry = float_or_texture(params, name, param);
  if (!entry) return std::nullopt;
  if (entry->textured())
    params.fail_at(*param, std::string(entry->image >= 0 ? "an image" : "a procedural") + " texture as \"" + name + "\" of " +
                               params.context() + " is not supported",
                   "only \"bumpmap\" reads a float texture here; the others take numbers");
  return entry->value[0];
}

// pbrt-v3's "bumpmap": the displacement, in scene units, is the float texture's
// value (a constant times an image's luminance or a pattern's value). A
// constant displaces every point alike and leaves the normals as they are.
std::optional<BumpMap> Importer::bump_map(ParamSet& params) {
  const Param* param = params.find("bumpmap", {ParamType::texture});
  if (!param) return std::nullopt;
  if (param->strings.size() != 1)
    fail(param->values, "\"texture bumpmap\" of " + params.context() + " takes 1 value, found " +
                            std::to_string(param->strings.size()));
  auto found = state_.float_textures->find(param->strings[0]);
  if (found == state_.float_textures->end())
    fail(param->values, "no float texture named \"" + param->strings[0] + "\"",
         "Texture \"" + param->strings[0] + "\" \"float\" ... defines one");
  const TextureEntry& entry = usable(found->second);
  if (!entry.textured()) return std::nullopt;
  double metres = entry.value[0] * options_.metres_per_unit;
  if (!std::isfinite(static_cast<Real>(metres)))
    params.fail_at(*param, "the bump map's displacement of " + params.context() + " is out of " + kRealName + " range");
  return BumpMap{.texture = entry.image, .pattern = entry.pattern, .scale = static_cast<Real>(metres) * units::meter};
}

// The largest value (per channel) of an image texture or a pattern, found
// once per texture: a noise pattern's is 16³ samples, and every material that
// reads the texture asks (twice for plastic and translucent).
Reflectance Importer::texture_maximum(int image, int pattern) {
  const auto [found, inserted] = texture_maxima_.try_emplace({image, pattern});
  if (inserted)
    found->second = image >= 0 ? result_.scene.textures[image].mipmap->maximum()
                               : largest_value(result_.scene.patterns[pattern].pattern);
  return found->second;
}

TexturedReflectance Importer::textured_reflectance(ParamSet& params, const char* name, double fallback, TextureUse use) {
  TextureEntry entry;
  entry.value = {fallback, fallback, fallback};
  const Param* param = nullptr;
  if (std::optional<TextureEntry> given = spectrum_or_texture(params, name, param)) entry = *given;
  if (entry.textured() && use == TextureUse::none)
    refuse_texture(params, *param, entry, name,
                   "only diffuse reflectances (\"Kd\" of matte, plastic, substrate, translucent and uber) take textures here");
  for (int c = 0; c < 3; ++c)
    if (!(entry.value[c] >= 0 && (entry.textured() || entry.value[c] <= 1)))
      params.fail_at(*param, "\"" + std::string(name) + "\" of " + params.context() + " must lie in [0, 1] in every channel",
                     "above 1 a surface reflects more light than it receives");
  // A texture's peaks above 1 (images scaled up, sums of noise: rs_pbrt's
  // wrinkled reaches 1.70) are what pbrt-v3 renders, clamping below 0 only.
  if (entry.textured() && !textures_above_one_warned_.count({entry.image, entry.pattern})) {
    const sg::vec3_rep texel = sg::raw(texture_maximum(entry.image, entry.pattern));
    double reaches = 0;
    for (int c = 0; c < 3; ++c) reaches = std::max(reaches, entry.value[c] * texel[c]);
    if (reaches > 1) {
      textures_above_one_warned_.insert({entry.image, entry.pattern});
      if (use == TextureUse::weight)
        warn(param->values,
             "this texture reaches " + format_number(reaches) + ": as \"" + std::string(name) + "\" of " +
                 params.context() + " it is clamped to 1 where it exceeds 1",
             "a weight lies in [0, 1]: pbrt-v3 clamps uber's opacity too, but would give a mix's second material a "
             "negative weight there");
      else
        warn(param->values,
             "this texture reaches " + format_number(reaches) + ": as \"" + std::string(name) + "\" of " +
                 params.context() + " the surface reflects more light than it receives where it exceeds 1",
             entry.pattern >= 0 && std::holds_alternative<MarblePattern>(result_.scene.patterns[entry.pattern].pattern)
                 ? "rendered as pbrt-v3 renders it: pbrt-v3's marble picks its spline segment as min(1, ⌊6t⌋) and so "
                   "extrapolates the second segment's cubic"
                 : "rendered as pbrt-v3 renders it; lower the texture (a \"scale\" texture) for a surface that conserves "
                   "energy");
    }
  }
  TexturedReflectance result;
  result.value = sg::from_raw<Reflectance>(sg::vec3_rep(static_cast<Real>(entry.value[0]), static_cast<Real>(entry.value[1]),
                                                        static_cast<Real>(entry.value[2])));
  result.texture = entry.image;
  result.pattern = entry.pattern;
  return result;
}

bool Importer::warned_above_one(const TexturedReflectance& kd) const {
  return kd.textured() && textures_above_one_warned_.count({kd.texture, kd.pattern});
}

Reflectance Importer::reflectance(ParamSet& params, const char* name, double fallback) {
  return textured_reflectance(params, name, fallback, TextureUse::none).value;
}

double Importer::roughness_alpha(ParamSet& params, const char* name, double fallback, bool remap) {
  return microfacet_alpha(float_param(params, name).value_or(fallback), remap);
}

// η or k of a metal: a constant (rgb, xyz, blackbody, a sampled or named
// spectrum, or a constant texture). η must be above 0 (the Fresnel equations
// divide by η² + k² at normal incidence), k at least 0 (0: a dielectric); the
// bound of 1000 keeps the equations' fourth powers inside float range.
IndexSpectrum Importer::index_spectrum(ParamSet& params, const char* name, const Rgb& fallback, bool zero_allowed) {
  TextureEntry entry;
  entry.value = fallback;
  const Param* param = nullptr;
  if (std::optional<TextureEntry> given = spectrum_or_texture(params, name, param)) entry = *given;
  if (entry.textured())
    refuse_texture(params, *param, entry, name,
                   "a metal's \"eta\" and \"k\" are constants here: rgb, a named spectrum or [wavelength value ...] pairs");
  for (double value : entry.value)
    if (!((zero_allowed ? value >= 0 : value > 0) && value <= 1000))
      params.fail_at(*param,
                     "\"" + std::string(name) + "\" of " + params.context() + " must lie in " +
                         (zero_allowed ? "[0, 1000]" : "(0, 1000]") + " in every channel, found " + format_rgb(entry.value),
                     zero_allowed ? "k is the extinction coefficient: 0 for a dielectric, copper's is 2.1 to 3.9"
                                  : "eta is the real part of the metal's index over the outside's: copper's is 0.2 to 1.1");
  return IndexSpectrum(static_cast<Real>(entry.value[0]), static_cast<Real>(entry.value[1]),
                       static_cast<Real>(entry.value[2]));
}

// pbrt-v3 reads "uroughness" and "vroughness" for an anisotropic lobe; the one
// here is isotropic, so they must agree. `reads_roughness`: the material also
// reads one "roughness" for both (substrate does not).
double Importer::isotropic_roughness(double u, double v, const ParamSet& params, SourceRange at, bool reads_roughness) {
  if (u != v)
    fail(at, "an anisotropic " + params.context() + " (\"uroughness\" " + format_number(u) + ", \"vroughness\" " +
                 format_number(v) + ") is not supported",
         reads_roughness ? "the microfacet lobe here is isotropic: give one \"roughness\""
                         : "the microfacet lobe here is isotropic: give \"uroughness\" and \"vroughness\" one value");
  return u;
}

// An alpha the renderer's precision holds (a huge unremapped roughness does not).
Real Importer::checked_alpha(double alpha, const ParamSet& params, SourceRange at) {
  Real value = static_cast<Real>(alpha);
  if (!std::isfinite(value)) fail(at, "the roughness of " + params.context() + " is out of " + kRealName + " range");
  return value;
}

double Importer::index_of_refraction(ParamSet& params, SourceRange at) {
  // pbrt-v3 reads "eta" and, only without it, "index".
  std::optional<double> eta = float_param(params, "eta");
  if (!eta) eta = float_param(params, "index");
  double value = eta.value_or(1.5);
  if (!(value >= 1.0 / 16 && value <= 16))
    fail(at, "the index of refraction (\"eta\") of " + params.context() + " must lie in [1/16, 16], found " +
                 format_number(value));
  return value;
}

// ---------------------------------------------------------------------------
// Materials

Material Importer::convert_material(const std::string& type, ParamSet& params, SourceRange at) {
  Material material;
  material.name = type;
  if (type == "uber") return convert_uber(params, at);
  if (type == "mix") return convert_mix(params, at);
  material.bump = bump_map(params);
  if (type == "matte") {
    // pbrt-v3's MatteMaterial: Oren-Nayar of "sigma" degrees (default 0: Lambert).
    const TexturedReflectance kd = textured_reflectance(params, "Kd", 0.5, TextureUse::reflectance);
    const double sigma = float_param(params, "sigma").value_or(0);
    if (!(sigma >= 0 && sigma <= 90))
      fail(at, "\"sigma\" of " + params.context() + " must lie in [0, 90] degrees, found " + format_number(sigma),
           "the standard deviation of the facets' slope angle");
    material.model = lambert_or_black(kd);
    if (sigma > 0 && !black(kd)) material.model = OrenNayarMaterial::with_sigma(kd, static_cast<Real>(sigma) * units::degree);
  } else if (type == "mirror") {
    Reflectance kr = reflectance(params, "Kr", 0.9);
    if (!sg::is_black(kr)) material.model = MirrorMaterial{kr};
  } else if (type == "plastic") {
    TexturedReflectance kd = textured_reflectance(params, "Kd", 0.25, TextureUse::reflectance);
    Reflectance ks = reflectance(params, "Ks", 0.25);
    bool remap = params.one_bool("remaproughness", true);
    // pbrt-v3's plastic: FresnelDielectric(1.5, 1), the indices swapped (mmp/pbrt-v3#210).
    material.model = plastic(kd, ks, roughness_alpha(params, "roughness", 0.1, remap), 1.5, true, params, at);
  } else if (type == "glass") {
    material.model = glass(params, at);
  } else if (type == "metal") {
    material.model = metal(params, at);
  } else if (type == "substrate") {
    material.model = substrate(params, at);
  } else if (type == "translucent") {
    material.model = translucent(params, at);
  } else if (type == "disney") {
    material.model = disney(params, at);
  }
  return material;
}

// pbrt-v3's uber is Lambert (Kd) + Fresnel-weighted microfacet reflection (Ks)
// + specular reflection (Kr) and transmission (Kt), all times opacity, plus a
// specular transmission of 1 − opacity that goes straight on (index 1). With
// either Kd/Ks or Kr/Kt black the lobes are exactly matte, plastic (with the
// Fresnel term the right way round: FresnelDielectric(1, eta)) or glass; with
// opacity below 1, that material mixed with a pass-through one, weighed by
// opacity: the same BSDF in expectation, a ray going on straight through with
// probability 1 − opacity (pbrt-v3's stochastic transparency).
Material Importer::convert_uber(ParamSet& params, SourceRange at) {
  Material material;
  material.name = "uber";
  material.bump = bump_map(params);
  const TexturedReflectance opacity = textured_reflectance(params, "opacity", 1, TextureUse::weight);
  TexturedReflectance kd = textured_reflectance(params, "Kd", 0.25, TextureUse::reflectance);
  Reflectance ks = reflectance(params, "Ks", 0.25), kr = reflectance(params, "Kr", 0), kt = reflectance(params, "Kt", 0);
  bool remap = params.one_bool("remaproughness", true);
  double roughness = float_param(params, "roughness").value_or(0.1);
  double u = float_param(params, "uroughness").value_or(roughness);
  u = isotropic_roughness(u, float_param(params, "vroughness").value_or(u), params, at);
  double eta = index_of_refraction(params, at);
  bool lobed = !black(kd) || !sg::is_black(ks), specular = !sg::is_black(kr) || !sg::is_black(kt);
  if (lobed && specular)
    fail(at, params.context() + " with both a diffuse or glossy part (Kd, Ks) and a specular one (Kr, Kt) is not supported",
         "no material here sums them; uber renders as matte, plastic or glass when one of the two parts is black");
  if (specular) {
    material.model = glass(kr, kt, eta);
  } else {
    material.model = plastic(kd, ks, microfacet_alpha(u, remap), eta, false, params, at);
  }
  if (!opacity.textured() && sg::raw(opacity.value) == sg::vec3_rep(1)) return material;
  return mixed_with_pass_through(std::move(material), opacity);
}

// `opaque` where `opacity` says, elsewhere a surface that light goes straight
// through (a specular transmission of index 1): a mix of the two.
Material Importer::mixed_with_pass_through(Material opaque, const TexturedReflectance& opacity) {
  std::vector<Material>& materials = result_.scene.materials;
  Material pass_through;
  pass_through.name = opaque.name + " (its transparent part)";
  pass_through.model = GlassMaterial{Reflectance{}, Reflectance(1.0f), 1.0f};
  Material mixed;
  mixed.name = opaque.name;
  materials.push_back(std::move(opaque));
  materials.push_back(std::move(pass_through));
  mixed.mix = MaterialMix{static_cast<int>(materials.size()) - 2, static_cast<int>(materials.size()) - 1, opacity};
  return mixed;
}

// pbrt-v3's MixMaterial: "namedmaterial1" weighted by "amount" (a spectrum,
// default 0.5), "namedmaterial2" by 1 − amount, each as it was made; no bump
// map of its own (each part keeps its own).
Material Importer::convert_mix(ParamSet& params, SourceRange at) {
  Material material;
  material.name = "mix";
  MaterialMix mix;
  mix.amount = textured_reflectance(params, "amount", 0.5, TextureUse::weight);
  mix.first = mixed_material(params, "namedmaterial1", at);
  mix.second = mixed_material(params, "namedmaterial2", at);
  material.mix = mix;
  return material;
}

// The Scene material of one of a mix's named materials. An undefined name is
// pbrt-v3's error message and a default matte, so a warning and the same here.
int Importer::mixed_material(ParamSet& params, const char* name, SourceRange at) {
  const Param* param = params.find(name, {ParamType::string});
  const std::string named = param && param->strings.size() == 1 ? param->strings[0] : "";
  auto found = state_.named_materials->find(named);
  if (found == state_.named_materials->end()) {
    warn(param ? param->values : at,
         "\"" + std::string(name) + "\" of " + params.context() +
             (named.empty() ? " is not given" : " names no material (\"" + named + "\")") + ": rendered as matte",
         "pbrt-v3 uses a default matte (Kd 0.5) there; MakeNamedMaterial defines one");
    Material matte;
    matte.name = "matte";
    matte.model = LambertMaterial{TexturedReflectance{Reflectance(0.5f)}};
    result_.scene.materials.push_back(matte);
    return static_cast<int>(result_.scene.materials.size()) - 1;
  }
  const MaterialInstance& instance = *found->second;
  if (instance.invisible)
    params.fail_at(*param, "\"" + std::string(name) + "\" of " + params.context() + " names a material \"" +
                               instance.type + "\", which is no surface",
                   "a mix of a surface and none would be a partly transparent surface, which pbrt-v3 does not make");
  const std::vector<Param> none;
  ParamSet no_overrides(none, params.context());
  return material_index(instance, no_overrides);
}

MaterialModel Importer::plastic(const TexturedReflectance& kd, Reflectance ks, double alpha, double ior,
                               bool pbrt_v3_fresnel, const ParamSet& params, SourceRange at) {
  if (sg::is_black(ks)) return lambert_or_black(kd);  // the Lambertian lobe alone, as pbrt-v3 builds it
  PlasticMaterial plastic{kd, ks, checked_alpha(alpha, params, at), static_cast<Real>(ior), pbrt_v3_fresnel};
  sg::vec3_rep largest = sg::raw(kd.value);
  if (kd.textured()) largest *= sg::raw(texture_maximum(kd.texture, kd.pattern));
  sg::vec3_rep sum = largest + sg::raw(ks);
  // pbrt-v3 renders it as it is (veach-mis has Kd 0.13 + Ks 1): so do we. A
  // texture above 1 on its own has been warned of already.
  if (std::max({sum.x, sum.y, sum.z}) > 1 && !warned_above_one(kd))
    warn(at, "\"Kd\" + \"Ks\" of " + params.context() + " exceed 1 in a channel (" +
                 format_number(std::max({sum.x, sum.y, sum.z})) + "): the surface can reflect more light than it receives",
         "rendered as pbrt-v3 renders it; lower Kd or Ks for a surface that conserves energy");
  return plastic;
}

// pbrt-v3's metal (src/materials/metal.cpp): a MicrofacetReflection of its
// FresnelConductor(1, η, k) and a Trowbridge–Reitz distribution; by default
// copper's η and k (its CopperN and CopperK, which are "metal-Cu-eta" and
// "metal-Cu-k") and roughness 0.01, remapped.
MaterialModel Importer::metal(ParamSet& params, SourceRange at) {
  static const Rgb copper_eta = *named_spectrum_rgb("metal-Cu-eta"), copper_k = *named_spectrum_rgb("metal-Cu-k");
  ConductorMaterial metal;
  metal.eta = index_spectrum(params, "eta", copper_eta, false);
  metal.k = index_spectrum(params, "k", copper_k, true);
  bool remap = params.one_bool("remaproughness", true);
  // Unlike uber's, metal's "vroughness" falls back to "roughness", not to "uroughness".
  double roughness = float_param(params, "roughness").value_or(0.01);
  double u = float_param(params, "uroughness").value_or(roughness), v = float_param(params, "vroughness").value_or(roughness);
  u = isotropic_roughness(u, v, params, at);
  metal.alpha = checked_alpha(microfacet_alpha(u, remap), params, at);
  return metal;
}

// pbrt-v3's substrate (src/materials/substrate.cpp): a FresnelBlend of "Kd"
// (0.5, textured as matte's) and "Ks" (0.5) over a Trowbridge–Reitz
// distribution of "uroughness" and "vroughness" (0.1 each; no "roughness"),
// remapped by default; no BxDF, so black, when both are black. Kd + Ks above
// 1 is no warning, unlike plastic's: FresnelBlend weights Kd by 1 − Ks.
MaterialModel Importer::substrate(ParamSet& params, SourceRange at) {
  TexturedReflectance kd = textured_reflectance(params, "Kd", 0.5, TextureUse::reflectance);
  Reflectance ks = reflectance(params, "Ks", 0.5);
  bool remap = params.one_bool("remaproughness", true);
  double u = float_param(params, "uroughness").value_or(0.1), v = float_param(params, "vroughness").value_or(0.1);
  u = isotropic_roughness(u, v, params, at, false);
  if (black(kd) && sg::is_black(ks)) return BlackMaterial{};
  return SubstrateMaterial{kd, ks, checked_alpha(microfacet_alpha(u, remap), params, at)};
}

// pbrt-v3's translucent (src/materials/translucent.cpp): "Kd" 0.25 (textured
// as matte's) and "Ks" 0.25, each split by "reflect" and "transmit" (0.5
// each) into lobes back and through, the glossy ones a Trowbridge–Reitz
// distribution of "roughness" 0.1, remapped by default, on an interface of
// index 1.5. No BxDF, so black, when reflect and transmit are both black, or
// Kd and Ks are.
MaterialModel Importer::translucent(ParamSet& params, SourceRange at) {
  TexturedReflectance kd = textured_reflectance(params, "Kd", 0.25, TextureUse::reflectance);
  Reflectance ks = reflectance(params, "Ks", 0.25);
  Reflectance reflect = reflectance(params, "reflect", 0.5), transmit = reflectance(params, "transmit", 0.5);
  bool remap = params.one_bool("remaproughness", true);
  Real alpha = checked_alpha(roughness_alpha(params, "roughness", 0.1, remap), params, at);
  if ((black(kd) && sg::is_black(ks)) || (sg::is_black(reflect) && sg::is_black(transmit))) return BlackMaterial{};
  // Each part sends reflect + transmit of what it scatters, so that bounds the
  // whole from the outside (from the inside, refraction concentrates radiance
  // by up to 1.5², as at any interface into a denser medium).
  sg::vec3_rep largest = sg::raw(kd.value);
  if (kd.textured()) largest *= sg::raw(texture_maximum(kd.texture, kd.pattern));
  const sg::vec3_rep bound = (largest + sg::raw(ks)) * (sg::raw(reflect) + sg::raw(transmit));
  if (std::max({bound.x, bound.y, bound.z}) > 1 && !warned_above_one(kd))  // pbrt-v3 renders it as it is: so do we
    warn(at, "(\"Kd\" + \"Ks\") * (\"reflect\" + \"transmit\") of " + params.context() + " exceeds 1 in a channel (" +
                 format_number(std::max({bound.x, bound.y, bound.z})) +
                 "): the surface may scatter more light than it receives",
         "rendered as pbrt-v3 renders it; lower them for a surface that conserves energy");
  return TranslucentMaterial{kd, ks, reflect, transmit, alpha, 1.5f};
}

// pbrt-v3's glass (src/materials/glass.cpp): "Kr" and "Kt" (1 each), "eta"
// (1.5); "uroughness" and "vroughness" (0 each), remapped by default. Smooth
// when both are 0: specular reflection and refraction. Rough, its BSDF is a
// Trowbridge–Reitz reflection lobe weighted by Kr and Walter et al.'s
// transmission lobe weighted by Kt on an interface of index eta, one of the
// two picked uniformly: exactly translucent's glossy lobes (Kd 0, Ks 1).
MaterialModel Importer::glass(ParamSet& params, SourceRange at) {
  Reflectance kr = reflectance(params, "Kr", 1), kt = reflectance(params, "Kt", 1);
  double u = float_param(params, "uroughness").value_or(0), v = float_param(params, "vroughness").value_or(0);
  u = isotropic_roughness(u, v, params, at, false);
  bool remap = params.one_bool("remaproughness", true);
  const double ior = index_of_refraction(params, at);
  if (u == 0) return glass(kr, kt, ior);
  if (sg::is_black(kr) && sg::is_black(kt)) return BlackMaterial{};
  return TranslucentMaterial{TexturedReflectance{}, Reflectance(1.0f), kr, kt,
                             checked_alpha(microfacet_alpha(u, remap), params, at), static_cast<Real>(ior)};
}

MaterialModel Importer::glass(Reflectance kr, Reflectance kt, double ior) {
  if (sg::is_black(kr) && sg::is_black(kt)) return BlackMaterial{};
  return GlassMaterial{kr, kt, static_cast<Real>(ior)};
}

void Importer::material(const Directive& d, bool named) {
  auto instance = std::make_shared<MaterialInstance>();
  instance->params = d.params;
  ParamSet params(instance->params, named ? "MakeNamedMaterial \"" + d.strings[0] + "\"" : "Material \"" + d.strings[0] + "\"");
  if (named) {
    const Param* type = params.find("type", {ParamType::string});
    if (!type || type->strings.size() != 1)
      fail(d.string_ranges[0], "MakeNamedMaterial \"" + d.strings[0] + "\" needs \"string type\", e.g. \"matte\"");
    instance->type = type->strings[0];
    instance->at = type->values;
  } else {
    instance->type = d.strings[0];
    instance->at = d.string_ranges[0];
  }
  try {
    make_material(*instance, params);
  } catch (const PbrtError& error) {
    instance->error = error.diagnostic();
  }
  if (named)
    writable(state_.named_materials)[d.strings[0]] = instance;
  else
    state_.material = instance;
}

void Importer::make_material(MaterialInstance& instance, ParamSet& params) {
  const std::string& type = instance.type;
  bool supported = false;
  for (const MaterialParams& m : kMaterialParams) supported = supported || m.type == type;
  if (type.empty() || type == "none") {  // no surface: pbrt-v3 makes no material, rays pass
    report_unused(params);
    instance.invisible = true;
    instance.index = -1;
    return;
  }
  if (!supported) fail(instance.at, "material \"" + type + "\" is not supported", kSupportedMaterials);
  Material converted = convert_material(type, params, instance.at);
  report_unused(params);
  if (absorbs_everything(converted)) {
    instance.index = -1;  // absorbs everything, as pbrt-v3's black matte does
  } else {
    instance.index = static_cast<int>(result_.scene.materials.size());
    result_.scene.materials.push_back(converted);
  }
}

int Importer::material_index(const MaterialInstance& material, ParamSet& shape_params) {
  if (material.error) throw PbrtError(*material.error);
  if (material.index != -2 && !reads_material_params(material.type, shape_params)) return material.index;
  // The shape's own values win over the material's.
  ParamSet material_params(material.params, "the shape's material \"" + material.type + "\"");
  shape_params.set_fallback(&material_params);
  Material converted = convert_material(material.type, shape_params, material.at);
  shape_params.set_fallback(nullptr);
  if (absorbs_everything(converted)) return -1;
  result_.scene.materials.push_back(converted);
  return static_cast<int>(result_.scene.materials.size()) - 1;
}

// ---------------------------------------------------------------------------
// Textures

void Importer::texture(const Directive& d) {
  const std::string &name = d.strings[0], &type = d.strings[1];
  bool spectrum = type == "spectrum" || type == "color";
  if (!spectrum && type != "float")
    fail(d.string_ranges[1], "texture type \"" + type + "\" is unknown", "pbrt-v3 has \"spectrum\" (or \"color\") and \"float\"");
  TextureEntry entry;
  try {
    entry = convert_texture(d, spectrum);
  } catch (const PbrtError& error) {
    entry.texture_class = d.strings[2];
    entry.at = d.string_ranges[2];
    entry.error = error.diagnostic();
  }
  writable(spectrum ? state_.spectrum_textures : state_.float_textures)[name] = entry;
}

TextureEntry Importer::convert_texture(const Directive& d, bool spectrum) {
  const std::string &name = d.strings[0], &texture_class = d.strings[2];
  ParamSet params(d.params, "Texture \"" + name + "\"");
  TextureEntry entry;
  entry.texture_class = texture_class;
  entry.at = d.string_ranges[2];
  if (texture_class == "constant") {
    if (spectrum) {
      std::optional<SpectrumValue> value = params.spectrum("value", false);
      entry.value = value ? value->rgb : Rgb{1, 1, 1};
    } else {
      double value = params.one_float("value", 1);
      entry.value = {value, value, value};
    }
  } else if (texture_class == "imagemap") {
    entry.image = image_texture(name, params, d.range);
  } else if (texture_class == "scale" || texture_class == "mix") {
    entry = combined_texture(name, texture_class, params, spectrum);
    entry.texture_class = texture_class;
    entry.at = d.string_ranges[2];
  } else if (std::optional<Pattern> made = pattern(texture_class, params, d.range, spectrum)) {
    result_.scene.patterns.push_back({name, std::move(*made)});
    entry.pattern = static_cast<int>(result_.scene.patterns.size()) - 1;
  } else {
    fail(entry.at, "texture \"" + texture_class + "\" is not supported", kSupportedTextures);
  }
  report_unused(params);
  return entry;
}

// pbrt-v3's ScaleTexture, tex1 × tex2 (each 1 by default), and MixTexture,
// (1 − amount) · tex1 + amount · tex2 (tex1 0, tex2 1, the float amount 0.5
// by default). Constants fold into one, and a constant times one image or
// pattern stays that; anything else becomes a pattern over its parts, which
// may be patterns but not images. A float texture's values are grey.
TextureEntry Importer::combined_texture(const std::string& name, const std::string& texture_class, ParamSet& params,
                                        bool spectrum) {
  const bool mix = texture_class == "mix";
  struct Operand {
    TextureEntry entry;
    const Param* param = nullptr;
  };
  auto operand = [&](const char* parameter, double fallback, bool as_spectrum) {
    Operand result;
    std::optional<TextureEntry> given = as_spectrum ? spectrum_or_texture(params, parameter, result.param)
                                                    : float_or_texture(params, parameter, result.param);
    if (given) result.entry = *given;
    else result.entry.value = {fallback, fallback, fallback};
    return result;
  };
  const Operand first = operand("tex1", mix ? 0 : 1, spectrum), second = operand("tex2", 1, spectrum);
  const Operand amount = mix ? operand("amount", 0.5, false) : Operand{};
  TextureEntry entry;
  const Operand* textured = nullptr;  // the one textured part, if only one is
  int textured_count = 0;
  for (const Operand* part : {&first, &second, &amount})
    if (part->entry.textured()) textured = part, ++textured_count;
  const double a = amount.entry.value[0];
  if (textured_count == 0) {
    for (int c = 0; c < 3; ++c)
      entry.value[c] = mix ? (1 - a) * first.entry.value[c] + a * second.entry.value[c]
                           : first.entry.value[c] * second.entry.value[c];
    return entry;
  }
  if (textured_count == 1 && textured != &amount) {
    // Linear in the textured part alone: a product, or a mix whose other part weighs 0.
    const Operand& other = textured == &first ? second : first;
    const double weight = textured == &first ? 1 - a : a;
    bool alone = true;
    for (int c = 0; c < 3; ++c) alone = alone && (!mix || (1 - weight) * other.entry.value[c] == 0);
    if (alone) {
      for (int c = 0; c < 3; ++c) entry.value[c] = textured->entry.value[c] * (mix ? weight : other.entry.value[c]);
      entry.image = textured->entry.image;
      entry.pattern = textured->entry.pattern;
      return entry;
    }
  }
  for (const Operand* part : {&first, &second, &amount})
    if (part->entry.image >= 0)
      params.fail_at(*part->param,
                     "an image texture in a \"" + texture_class + "\" with another texture is not supported",
                     "the renderer combines procedural textures (and constants), and multiplies one image by a "
                     "constant");
  auto pattern_operand = [&](const TextureEntry& e) {
    PatternOperand result;
    result.value = sg::from_raw<Reflectance>(sg::vec3_rep(static_cast<Real>(e.value[0]), static_cast<Real>(e.value[1]),
                                                           static_cast<Real>(e.value[2])));
    if (e.pattern >= 0) result.pattern = std::make_shared<const ProceduralTexture>(result_.scene.patterns[e.pattern]);
    return result;
  };
  Pattern combined = mix ? Pattern{MixPattern{pattern_operand(first.entry), pattern_operand(second.entry),
                                              pattern_operand(amount.entry)}}
                         : Pattern{ProductPattern{pattern_operand(first.entry), pattern_operand(second.entry)}};
  result_.scene.patterns.push_back({name, std::move(combined)});
  entry.pattern = static_cast<int>(result_.scene.patterns.size()) - 1;
  return entry;
}

// pbrt-v3's CreateImageSpectrumTexture: a (u, v) mapping, a wrap mode, a
// scale, the image flipped so that t = 0 is its bottom row, sRGB-decoded when
// "gamma" (by default for .png and .tga files, which it reads as 8-bit sRGB).
int Importer::image_texture(const std::string& name, ParamSet& params, SourceRange at) {
  const Param* filename = params.find("filename", {ParamType::string});
  if (!filename || filename->strings.size() != 1)
    fail(at, "Texture \"" + name + "\" \"imagemap\" needs \"string filename\"");
  ImageTexture texture;
  texture.name = name;
  texture.file = filename->strings[0];
  std::string extension = lower_extension(texture.file);
  // pbrt-v3 decodes .png and .tga; the other 8-bit formats read here beyond
  // pbrt-v3's are sRGB-encoded as well.
  bool eight_bit = extension == ".png" || extension == ".tga" || extension == ".jpg" || extension == ".jpeg" ||
                   extension == ".bmp" || extension == ".gif";
  texture.colour_space = params.one_bool("gamma", eight_bit) ? ColourSpace::srgb : ColourSpace::linear;
  double scale = params.one_float("scale", 1);
  if (!(scale >= 0 && scale <= 1e6)) fail(at, "\"float scale\" of " + params.context() + " must lie in [0, 1e6]");
  texture.scale = static_cast<Real>(scale);
  texture.mapping = mapping_2d(params, at);
  std::string wrap_name = params.one_string("wrap", "repeat");
  TextureWrap wrap = TextureWrap::repeat;
  if (wrap_name == "black") wrap = TextureWrap::black;
  else if (wrap_name == "clamp") wrap = TextureWrap::clamp;
  else if (wrap_name != "repeat")
    params.fail_at(*params.find("wrap", {ParamType::string}), "wrap mode \"" + wrap_name + "\" is unknown",
                   "pbrt-v3 has \"repeat\", \"black\" and \"clamp\" (and would silently repeat)");
  // pbrt-v3 filters over its ray differentials scaled by 1/sqrt(spp)
  // (SamplerIntegrator::Render); we filter over the ray cone, narrowed alike,
  // whose ellipse on the surface is the differentials' (EWA), or its long axis (trilinear).
  texture.filter = params.one_bool("trilinear", false) ? TextureFilter::trilinear : TextureFilter::ewa;
  const double max_anisotropy = params.one_float("maxanisotropy", 8);
  if (!(max_anisotropy > 0 && max_anisotropy <= 1e6))
    params.fail_at(*params.find("maxanisotropy", {ParamType::floating}),
                   "\"float maxanisotropy\" of " + params.context() + " must lie in (0, 1e6]");
  texture.max_anisotropy = static_cast<Real>(max_anisotropy);
  Image image = read_image(*filename);
  texture.mipmap = std::make_shared<MipMap>(
      to_linear_texels(std::move(image), texture.colour_space, static_cast<float>(scale), true), wrap);
  result_.scene.textures.push_back(std::move(texture));
  return static_cast<int>(result_.scene.textures.size()) - 1;
}

// An image file named by `filename` (a texture's or an infinite light's map),
// resolved as pbrt-v3 resolves it (against the main file's directory), through
// PbrtImportOptions::read_image. A format pbrt-v3 does not read (.hdr maps are
// common in scene collections) is read all the same: pbrt-v3 would render a
// grey texture or the light's constant radiance, which is not what the scene's
// author meant; the warning says so, once per format.
Image Importer::read_image(const Param& filename) {
  const std::string& file = filename.strings[0];
  std::string extension = lower_extension(file);
  if (extension != ".exr" && extension != ".png" && extension != ".tga" && extension != ".pfm" &&
      formats_beyond_pbrt_warned_.insert(extension).second)
    warn(filename.values, "pbrt-v3 reads no image format \"" + extension + "\"; read here as the file says",
         "pbrt-v3 reads .exr, .png, .tga and .pfm files: it would render a grey texture, or an infinite light's "
         "constant radiance without its map");
  std::filesystem::path path = file;
  if (path.is_relative()) path = search_directory_ / path;
  try {
    return read_checked_image(path, options_.read_image);
  } catch (const std::exception& error) {
    fail(filename.values, "cannot read image '" + path.string() + "': " + error.what());
  }
}

}  // namespace safegi::render::pbrt
