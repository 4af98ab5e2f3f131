#include <algorithm>
#include <cctype>
#include <cmath>

#include "scene/json_loader.hpp"
#include "pbrt/pbrt_colour.hpp"

namespace safegi::render::json {

Image Loader::read_image_file(const Json& file_value, const JsonPath& path, std::string& file) {
  file = string(file_value, path);
  std::filesystem::path full = base_directory_ / file;
  if (!std::filesystem::is_regular_file(full)) fail(path, "cannot read image '" + file + "': no such file");
  try {
    return read_checked_image(full, options_.read_image);
  } catch (const std::exception& error) {
    fail(path, "cannot read image '" + file + "': " + error.what());
  }
}

ImageTexture Loader::load_texture(const std::string& name, const Json& value, const JsonPath& path) {
  if (!value.is_object()) fail(path, "expected an object, got " + short_dump(value));
  std::string type = string(required(value, path, "type"), path.field("type"));
  if (type != "image") fail(path.field("type"), "expected \"image\", got " + short_dump(value["type"]));
  object(value, path, {"type", "file", "colour_space", "filter", "max_anisotropy", "wrap", "scale", "uv_scale", "uv_offset"});
  ImageTexture texture;
  texture.name = name;
  Image image = read_image_file(required(value, path, "file"), path.field("file"), texture.file);
  // 8-bit images are painted in sRGB; floating-point formats hold linear values.
  std::string extension = std::filesystem::path(texture.file).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  bool linear_format = extension == ".exr" || extension == ".hdr" || extension == ".pfm";
  texture.colour_space = linear_format ? ColourSpace::linear : ColourSpace::srgb;
  if (value.contains("colour_space")) {
    std::string space = string(value["colour_space"], path.field("colour_space"));
    if (space == "srgb") texture.colour_space = ColourSpace::srgb;
    else if (space == "linear") texture.colour_space = ColourSpace::linear;
    else fail(path.field("colour_space"), "expected \"srgb\" or \"linear\", got " + short_dump(value["colour_space"]));
  }
  if (value.contains("filter")) {
    std::string filter = string(value["filter"], path.field("filter"));
    if (filter == "bilinear") texture.filter = TextureFilter::bilinear;
    else if (filter == "trilinear") texture.filter = TextureFilter::trilinear;
    else if (filter == "ewa") texture.filter = TextureFilter::ewa;
    else fail(path.field("filter"), "expected \"bilinear\", \"trilinear\" or \"ewa\", got " + short_dump(value["filter"]));
  }
  if (value.contains("max_anisotropy"))
    texture.max_anisotropy = number(value["max_anisotropy"], path.field("max_anisotropy"), 1, 1e6);
  TextureWrap wrap = TextureWrap::repeat;
  if (value.contains("wrap")) {
    std::string mode = string(value["wrap"], path.field("wrap"));
    if (mode == "repeat") wrap = TextureWrap::repeat;
    else if (mode == "clamp") wrap = TextureWrap::clamp;
    else if (mode == "black") wrap = TextureWrap::black;
    else fail(path.field("wrap"), "expected \"repeat\", \"clamp\" or \"black\", got " + short_dump(value["wrap"]));
  }
  if (value.contains("scale")) texture.scale = number(value["scale"], path.field("scale"), 0, 1e6);
  auto pair = [&](const char* field, Real& a, Real& b) {
    if (!value.contains(field)) return;
    const Json& v = value[field];
    if (!v.is_array() || v.size() != 2) fail(path.field(field), "expected [u, v], got " + short_dump(v));
    a = number(v[0], path.field(field).index(0), -1e6, 1e6);
    b = number(v[1], path.field(field).index(1), -1e6, 1e6);
  };
  pair("uv_scale", texture.mapping.u_scale, texture.mapping.v_scale);
  pair("uv_offset", texture.mapping.u_offset, texture.mapping.v_offset);
  // Texels are stored as float in every build (8 to 32 bits of data per channel).
  texture.mipmap = std::make_shared<MipMap>(
      to_linear_texels(std::move(image), texture.colour_space, static_cast<float>(texture.scale), true), wrap);
  return texture;
}

TexturedReflectance Loader::textured_reflectance(const Json& value, const JsonPath& path) {
  if (value.is_object() && value.contains("texture")) {
    object(value, path, {"texture"});
    std::string name = string(value["texture"], path.field("texture"));
    auto found = texture_index_.find(name);
    if (found == texture_index_.end()) fail(path.field("texture"), "no texture named " + short_dump(value["texture"]));
    if (sg::max_component(textures_[found->second]->maximum()) > 1.0f)
      fail(path.field("texture"), "texture " + short_dump(value["texture"]) +
                                      " has values above 1 and cannot be a reflectance (check its scale)");
    return {Reflectance(1.0f), found->second};
  }
  return {reflectance(value, path), -1};
}

Reflectance Loader::largest_diffuse(const TexturedReflectance& diffuse) const {
  return diffuse.texture < 0 ? diffuse.value : diffuse.value * textures_[diffuse.texture]->maximum();
}

// η must be above 0 (the Fresnel equations divide by η² + k² at normal
// incidence); k = 0 is a dielectric. The bound of 1000 keeps the equations'
// fourth powers well inside float range. A measured metal may be named as
// pbrt-v4 names it ("metal-Au-eta"), converted to RGB as the pbrt importer does.
IndexSpectrum Loader::index_spectrum(const Json& value, const JsonPath& path, bool zero_allowed) {
  if (value.is_string()) {
    std::optional<std::array<double, 3>> named = pbrt::named_spectrum_rgb(value.get<std::string>());
    if (!named)
      fail(path, "expected a number, [r, g, b] or a named spectrum (" + pbrt::named_spectrum_names() + "), got " +
                     short_dump(value));
    return IndexSpectrum(static_cast<Real>((*named)[0]), static_cast<Real>((*named)[1]), static_cast<Real>((*named)[2]));
  }
  IndexSpectrum index = typed_spectrum<dim::dimensionless>(value, path);
  for (int c = 0; c < 3; ++c)
    if (!((zero_allowed ? index[c] >= 0 : index[c] > 0) && index[c] <= 1000))
      fail(path, std::string("expected ") + (zero_allowed ? "values in [0, 1000]" : "values in (0, 1000]") +
                     " in every channel, got " + short_dump(value));
  return index;
}

Material Loader::load_material(const std::string& name, const Json& value, const JsonPath& path) {
  if (!value.is_object()) fail(path, "expected an object, got " + short_dump(value));
  std::string type = string(required(value, path, "type"), path.field("type"));
  Material material;
  material.name = name;
  // Phong and plastic reflect their two parts' sum.
  auto require_energy_conservation = [&](const TexturedReflectance& diffuse, Reflectance specular) {
    if (sg::max_component(largest_diffuse(diffuse) + specular) > 1.0f)
      fail(path, "diffuse + specular must not exceed 1 in any channel (energy conservation)");
  };
  if (type == "lambert") {
    object(value, path, {"type", "reflectance"});
    material.model = LambertMaterial{textured_reflectance(required(value, path, "reflectance"), path.field("reflectance"))};
  } else if (type == "oren_nayar") {
    object(value, path, {"type", "reflectance", "sigma"});
    const Angle sigma = typed_scalar<dim::angle>(required(value, path, "sigma"), path.field("sigma"));
    if (!(sigma >= Real(0) * units::degree && sigma <= Real(90) * units::degree))
      fail(path.field("sigma"), "expected an angle in [0 deg, 90 deg], got " + short_dump(value["sigma"]));
    material.model = OrenNayarMaterial::with_sigma(
        textured_reflectance(required(value, path, "reflectance"), path.field("reflectance")), sigma);
  } else if (type == "phong") {
    object(value, path, {"type", "diffuse", "specular", "exponent"});
    PhongMaterial phong;
    phong.diffuse = textured_reflectance(required(value, path, "diffuse"), path.field("diffuse"));
    phong.specular = reflectance(required(value, path, "specular"), path.field("specular"));
    double exponent = scalar(required(value, path, "exponent"), path.field("exponent"), runtime_dim::none);
    if (!(exponent >= 0 && exponent <= 1e6)) fail(path.field("exponent"), "expected a number in [0, 1e6]");
    phong.exponent = static_cast<Real>(exponent);
    require_energy_conservation(phong.diffuse, phong.specular);
    material.model = phong;
  } else if (type == "mirror") {
    object(value, path, {"type", "reflectance"});
    material.model = MirrorMaterial{reflectance(required(value, path, "reflectance"), path.field("reflectance"))};
  } else if (type == "glass") {
    object(value, path, {"type", "ior", "reflectance", "transmittance", "alpha"});
    GlassMaterial glass;
    glass.ior = number(required(value, path, "ior"), path.field("ior"), 1.0 / 16, 16);
    glass.reflectance = value.contains("reflectance") ? reflectance(value["reflectance"], path.field("reflectance"))
                                                      : Reflectance(1.0f);
    glass.transmittance = value.contains("transmittance")
                              ? reflectance(value["transmittance"], path.field("transmittance"))
                              : Reflectance(1.0f);
    material.model = glass;
    // Rough glass is pbrt-v3's: translucent's glossy lobes alone, on an interface of this index.
    if (value.contains("alpha"))
      material.model = TranslucentMaterial{TexturedReflectance{}, Reflectance(1.0f), glass.reflectance, glass.transmittance,
                                           static_cast<Real>(number(value["alpha"], path.field("alpha"), 1e-4, 1)), glass.ior};
  } else if (type == "plastic") {
    object(value, path, {"type", "diffuse", "specular", "alpha", "ior", "pbrt_v3_fresnel"});
    PlasticMaterial plastic;
    plastic.diffuse = textured_reflectance(required(value, path, "diffuse"), path.field("diffuse"));
    plastic.specular = reflectance(required(value, path, "specular"), path.field("specular"));
    plastic.alpha = number(required(value, path, "alpha"), path.field("alpha"), 1e-4, 1);
    if (value.contains("ior")) plastic.ior = number(value["ior"], path.field("ior"), 1, 16);
    if (value.contains("pbrt_v3_fresnel"))
      plastic.pbrt_v3_fresnel = boolean(value["pbrt_v3_fresnel"], path.field("pbrt_v3_fresnel"));
    require_energy_conservation(plastic.diffuse, plastic.specular);
    material.model = plastic;
  } else if (type == "conductor") {
    object(value, path, {"type", "eta", "k", "alpha"});
    ConductorMaterial metal;
    metal.eta = index_spectrum(required(value, path, "eta"), path.field("eta"), false);
    metal.k = index_spectrum(required(value, path, "k"), path.field("k"), true);
    metal.alpha = number(required(value, path, "alpha"), path.field("alpha"), 1e-4, 1);
    material.model = metal;
  } else if (type == "substrate") {
    // No energy check: FresnelBlend weights the diffuse part by 1 − specular.
    object(value, path, {"type", "diffuse", "specular", "alpha"});
    SubstrateMaterial substrate;
    substrate.diffuse = textured_reflectance(required(value, path, "diffuse"), path.field("diffuse"));
    substrate.specular = reflectance(required(value, path, "specular"), path.field("specular"));
    substrate.alpha = number(required(value, path, "alpha"), path.field("alpha"), 1e-4, 1);
    material.model = substrate;
  } else if (type == "translucent") {
    object(value, path, {"type", "diffuse", "specular", "reflect", "transmit", "alpha"});
    TranslucentMaterial translucent;
    translucent.diffuse = textured_reflectance(required(value, path, "diffuse"), path.field("diffuse"));
    translucent.specular = reflectance(required(value, path, "specular"), path.field("specular"));
    translucent.reflect = reflectance(required(value, path, "reflect"), path.field("reflect"));
    translucent.transmit = reflectance(required(value, path, "transmit"), path.field("transmit"));
    translucent.alpha = number(required(value, path, "alpha"), path.field("alpha"), 1e-4, 1);
    // Both parts send reflect + transmit of what they scatter: seen from the
    // outside, the surface scatters at most this product.
    if (sg::max_component((largest_diffuse(translucent.diffuse) + translucent.specular) *
                          (translucent.reflect + translucent.transmit)) > 1.0f)
      fail(path, "(diffuse + specular) * (reflect + transmit) must not exceed 1 in any channel (energy conservation)");
    material.model = translucent;
  } else if (type == "mix") {
    // Its parts are named; resolve_mix finds them once every material is loaded.
    object(value, path, {"type", "first", "second", "amount"});
    MaterialMix mix;
    mix.amount = textured_reflectance(required(value, path, "amount"), path.field("amount"));
    string(required(value, path, "first"), path.field("first"));
    string(required(value, path, "second"), path.field("second"));
    material.mix = mix;
  } else {
    fail(path.field("type"),
         "expected \"lambert\", \"oren_nayar\", \"phong\", \"mirror\", \"glass\", \"plastic\", \"conductor\", \"substrate\", "
         "\"translucent\" or \"mix\", got " +
             short_dump(value["type"]));
  }
  return material;
}

void Loader::resolve_mix(Scene& scene, int index, const Json& value, const JsonPath& path,
                         const std::map<std::string, int>& material_index) {
  MaterialMix& mix = *scene.materials[index].mix;
  for (auto [part, field] : {std::pair{&mix.first, "first"}, std::pair{&mix.second, "second"}}) {
    auto found = material_index.find(string(value[field], path.field(field)));
    if (found == material_index.end()) fail(path.field(field), "no material named " + short_dump(value[field]));
    *part = found->second;
  }
  // Before this one, the resolved mixes formed no circle: a new one passes through it.
  std::vector<bool> visited(scene.materials.size());
  std::vector<int> reached{mix.first, mix.second};
  while (!reached.empty()) {
    const int at = reached.back();
    reached.pop_back();
    if (at == index) fail(path, "mix " + short_dump(scene.materials[index].name) + " contains itself");
    if (at < 0 || visited[at]) continue;  // -1: a mix whose parts are not resolved yet
    visited[at] = true;
    if (const std::optional<MaterialMix>& part = scene.materials[at].mix) {
      reached.push_back(part->first);
      reached.push_back(part->second);
    }
  }
}

}  // namespace safegi::render::json
