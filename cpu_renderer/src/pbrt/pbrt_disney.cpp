// The importer's pbrt-v3 "disney" material (src/materials/disney.cpp's
// CreateDisneyMaterial): its parameters and defaults, onto DisneyMaterial.
// What the renderer does not model is an error at the parameter that asks for
// it: an anisotropic lobe (no surface tangent orients it) and subsurface
// scattering (a non-black "scatterdistance").
#include <cmath>

#include "pbrt/pbrt_importer.hpp"

namespace safegi::render::pbrt {

// A float parameter of "disney": a number or a constant float texture in [low, high].
Real Importer::disney_float(ParamSet& params, const char* name, double fallback, double low, double high) {
  const Param* param = nullptr;
  std::optional<TextureEntry> entry = float_or_texture(params, name, param);
  if (!entry) return static_cast<Real>(fallback);
  if (entry->textured())
    params.fail_at(*param,
                   std::string(entry->image >= 0 ? "an image" : "a procedural") + " texture as \"" + name + "\" of " +
                       params.context() + " is not supported",
                   "\"disney\" reads its float parameters as numbers here; \"color\" and \"bumpmap\" take textures");
  const double value = entry->value[0];
  if (!(value >= low && value <= high))
    params.fail_at(*param, "\"" + std::string(name) + "\" of " + params.context() + " must lie in [" + format_number(low) +
                               ", " + format_number(high) + "], found " + format_number(value));
  return static_cast<Real>(value);
}

MaterialModel Importer::disney(ParamSet& params, SourceRange) {
  DisneyMaterial d;
  d.diffuse = textured_reflectance(params, "color", 0.5, TextureUse::reflectance);
  d.metallic = disney_float(params, "metallic", 0, 0, 1);
  d.eta = disney_float(params, "eta", 1.5, 1.0 / 16, 16);
  d.roughness = disney_float(params, "roughness", 0.5, 0, 1);
  d.specular_tint = disney_float(params, "speculartint", 0, 0, 1);
  d.anisotropic = disney_float(params, "anisotropic", 0, 0, 1);
  if (d.anisotropic != 0)
    params.fail_at(*params.find("anisotropic", {ParamType::floating, ParamType::texture}),
                   "an anisotropic " + params.context() + " (\"anisotropic\" " + format_number(d.anisotropic) +
                       ") is not supported",
                   "the renderer's shading frames have no surface tangent (pbrt-v3's dp/du) to orient the lobe by; "
                   "\"anisotropic\" 0 is isotropic");
  d.sheen = disney_float(params, "sheen", 0, 0, 1);
  d.sheen_tint = disney_float(params, "sheentint", 0.5, 0, 1);
  d.clearcoat = disney_float(params, "clearcoat", 0, 0, 1);
  d.clearcoat_gloss = disney_float(params, "clearcoatgloss", 1, 0, 1);
  d.spec_trans = disney_float(params, "spectrans", 0, 0, 1);

  // pbrt-v3 replaces the diffuse lobe by a BSSRDF where "scatterdistance" is not black.
  const Param* distance = nullptr;
  if (std::optional<TextureEntry> sd = spectrum_or_texture(params, "scatterdistance", distance))
    if (sd->textured() || sd->value != Rgb{0, 0, 0})
      params.fail_at(*distance, "subsurface scattering (\"scatterdistance\") of " + params.context() + " is not supported",
                     "pbrt-v3 renders the diffuse part by its BSSRDF there; a black \"scatterdistance\" (the default) is "
                     "Burley's diffuse");
  d.thin = params.one_bool("thin", false);
  if (d.thin) {
    d.flatness = disney_float(params, "flatness", 0, 0, 1);
    // pbrt-v3 transmits difftrans/2 of the diffuse light: up to 2 sends it all through.
    d.diff_trans = disney_float(params, "difftrans", 1, 0, 2);
  } else {
    // Read by pbrt-v3 for thin surfaces only.
    for (const char* name : {"flatness", "difftrans"}) {
      const Param* param = nullptr;
      if (float_or_texture(params, name, param))
        warn(param->declaration, "parameter \"" + param->type_name + " " + param->name + "\" of " + params.context() +
                                     " is not used: it applies to thin surfaces (\"bool thin\" true) only",
             "pbrt-v3 ignores it too without \"thin\"");
    }
  }
  return d;
}

}  // namespace safegi::render::pbrt
