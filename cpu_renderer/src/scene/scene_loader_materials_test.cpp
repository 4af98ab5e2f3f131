// The scene format's materials, textures and environment light: what each
// field becomes, and the exact message when one is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "safegi/cpu_renderer/image.hpp"
#include "pbrt/pbrt_colour.hpp"
#include "safegi/cpu_renderer/scene_loader.hpp"

namespace safegi::render {
namespace {

namespace fs = std::filesystem;

std::string with_camera(const std::string& rest) {
  return std::string(R"j({"camera": {"position": {"value": [0, 0, 5], "unit": "m"}, "look_at": {"value": [0, 0, 0], "unit": "m"},
                          "up": [0, 1, 0], "fov": "40 deg"})j") +
         (rest.empty() ? "" : ", " + rest) + "}";
}

// A temporary folder with a 2×2 PFM image whose texels are 0, 0.25, 0.5, 1 (grey), top row first.
class LoaderFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = fs::temp_directory_path() / ("safegi-loader-materials-" + std::to_string(::getpid()));
    fs::create_directories(directory_);
    Image image{2, 2, {0, 0, 0, 0.25f, 0.25f, 0.25f, 0.5f, 0.5f, 0.5f, 1, 1, 1}};
    write_pfm(directory_ / "grey.pfm", image);
    std::ofstream(directory_ / "photo.png") << "not really a png";
  }
  void TearDown() override { fs::remove_all(directory_); }

  Scene load(const std::string& json) { return parse_scene(json, "test.json", directory_); }
  std::string error(const std::string& json) {
    try {
      load(json);
    } catch (const SceneError& e) {
      return e.what();
    }
    ADD_FAILURE() << "no error for " << json;
    return "";
  }

  fs::path directory_;
};

TEST_F(LoaderFiles, GlassAndPlastic) {
  Scene scene = load(with_camera(R"j("materials": {
      "glass": {"type": "glass", "ior": 1.33},
      "tinted": {"type": "glass", "ior": 1.5, "reflectance": 0.9, "transmittance": [0.2, 0.8, 0.9]},
      "plastic": {"type": "plastic", "diffuse": [0.5, 0.2, 0.1], "specular": 0.3, "alpha": 0.05, "pbrt_v3_fresnel": true}})j"));
  ASSERT_EQ(scene.materials.size(), 3u);
  auto named = [&](const std::string& name) -> const Material& {
    for (const Material& m : scene.materials)
      if (m.name == name) return m;
    throw std::runtime_error("no material " + name);
  };
  ASSERT_TRUE(std::holds_alternative<GlassMaterial>(named("glass").model));
  const auto& glass = std::get<GlassMaterial>(named("glass").model);
  EXPECT_FLOAT_EQ(glass.ior, 1.33f);
  EXPECT_EQ(sg::raw(glass.reflectance), glm::vec3(1.0f));
  EXPECT_EQ(sg::raw(glass.transmittance), glm::vec3(1.0f));
  EXPECT_EQ(sg::raw(std::get<GlassMaterial>(named("tinted").model).transmittance), glm::vec3(0.2f, 0.8f, 0.9f));
  ASSERT_TRUE(std::holds_alternative<PlasticMaterial>(named("plastic").model));
  const auto& plastic = std::get<PlasticMaterial>(named("plastic").model);
  EXPECT_FLOAT_EQ(plastic.alpha, 0.05f);
  EXPECT_FLOAT_EQ(plastic.ior, 1.5f);
  EXPECT_TRUE(plastic.pbrt_v3_fresnel);
  EXPECT_EQ(plastic.diffuse.texture, -1);

  EXPECT_EQ(error(with_camera(R"j("materials": {"g": {"type": "glass"}})j")), "test.json: materials.g: missing field 'ior'");
  EXPECT_EQ(error(with_camera(R"j("materials": {"g": {"type": "glass", "ior": 0}})j")),
            "test.json: materials.g.ior: expected a number in [0.0625, 16], got 0");
  EXPECT_EQ(error(with_camera(R"j("materials": {"g": {"type": "glass", "ior": "1.5 m"}})j")),
            "test.json: materials.g.ior: expected dimensionless number (e.g. 0.5), got \"1.5 m\" (length)");
  EXPECT_EQ(error(with_camera(R"j("materials": {"p": {"type": "plastic", "diffuse": 0.7, "specular": 0.5, "alpha": 0.1}})j")),
            "test.json: materials.p: diffuse + specular must not exceed 1 in any channel (energy conservation)");
  EXPECT_EQ(error(with_camera(R"j("materials": {"p": {"type": "plastic", "diffuse": 0.5, "specular": 0.5, "alpha": 0}})j")),
            "test.json: materials.p.alpha: expected a number in [0.0001, 1], got 0");
  EXPECT_EQ(error(with_camera(R"j("materials": {"p": {"type": "wood"}})j")),
            "test.json: materials.p.type: expected \"lambert\", \"oren_nayar\", \"phong\", \"mirror\", \"glass\", \"plastic\", "
            "\"conductor\", \"substrate\", \"translucent\" or \"mix\", got \"wood\"");
}

TEST_F(LoaderFiles, Conductor) {
  Scene scene = load(with_camera(R"j("materials": {
      "copper": {"type": "conductor", "eta": [0.2, 0.92, 1.1], "k": [3.9, 2.45, 2.14], "alpha": 0.1},
      "gold": {"type": "conductor", "eta": "metal-Au-eta", "k": "metal-Au-k", "alpha": 0.01},
      "grey": {"type": "conductor", "eta": 1.5, "k": 0, "alpha": 1}})j"));
  ASSERT_EQ(scene.materials.size(), 3u);
  auto metal = [&](const std::string& name) {
    for (const Material& m : scene.materials)
      if (m.name == name) return std::get<ConductorMaterial>(m.model);
    throw std::runtime_error("no material " + name);
  };
  EXPECT_EQ(sg::raw(metal("copper").eta), glm::vec3(0.2f, 0.92f, 1.1f));
  EXPECT_EQ(sg::raw(metal("copper").k), glm::vec3(3.9f, 2.45f, 2.14f));
  EXPECT_FLOAT_EQ(metal("copper").alpha, 0.1f);
  std::array<double, 3> gold_eta = *pbrt::named_spectrum_rgb("metal-Au-eta"), gold_k = *pbrt::named_spectrum_rgb("metal-Au-k");
  for (int c = 0; c < 3; ++c) {
    EXPECT_FLOAT_EQ(metal("gold").eta[c], static_cast<float>(gold_eta[c]));
    EXPECT_FLOAT_EQ(metal("gold").k[c], static_cast<float>(gold_k[c]));
  }
  EXPECT_EQ(sg::raw(metal("grey").eta), glm::vec3(1.5f));
  EXPECT_EQ(sg::raw(metal("grey").k), glm::vec3(0.0f));

  auto conductor_error = [&](const std::string& fields) {
    return error(with_camera(R"j("materials": {"m": {"type": "conductor", )j" + fields + "}}"));
  };
  EXPECT_EQ(conductor_error(R"j("eta": 1, "alpha": 0.1)j"), "test.json: materials.m: missing field 'k'");
  EXPECT_EQ(conductor_error(R"j("eta": [0.2, 0, 1], "k": 1, "alpha": 0.1)j"),
            "test.json: materials.m.eta: expected values in (0, 1000] in every channel, got [0.2,0,1]");
  EXPECT_EQ(conductor_error(R"j("eta": 1, "k": -1, "alpha": 0.1)j"),
            "test.json: materials.m.k: expected values in [0, 1000] in every channel, got -1");
  EXPECT_EQ(conductor_error(R"j("eta": 1, "k": 1, "alpha": 0)j"),
            "test.json: materials.m.alpha: expected a number in [0.0001, 1], got 0");
  EXPECT_EQ(conductor_error(R"j("eta": "metal-Xx-eta", "k": 1, "alpha": 0.1)j"),
            "test.json: materials.m.eta: expected a number, [r, g, b] or a named spectrum (\"metal-Ag-eta\", "
            "\"metal-Ag-k\", \"metal-Al-eta\", \"metal-Al-k\", \"metal-Au-eta\", \"metal-Au-k\", \"metal-Cu-eta\", "
            "\"metal-Cu-k\", \"metal-CuZn-eta\", \"metal-CuZn-k\"), got \"metal-Xx-eta\"");
  EXPECT_EQ(conductor_error(R"j("eta": 1, "k": 1, "alpha": 0.1, "roughness": 0.1)j"),
            "test.json: materials.m.roughness: unknown field (expected one of: type, eta, k, alpha)");
}

// pbrt-v3's substrate: diffuse + specular above 1 is accepted (FresnelBlend
// weights the diffuse part by 1 - specular), unlike plastic's.
TEST_F(LoaderFiles, Substrate) {
  Scene scene = load(with_camera(R"j("materials": {
      "s": {"type": "substrate", "diffuse": [0.7, 0.5, 0.3], "specular": 0.6, "alpha": 0.05}})j"));
  ASSERT_EQ(scene.materials.size(), 1u);
  const SubstrateMaterial& substrate = std::get<SubstrateMaterial>(scene.materials[0].model);
  EXPECT_EQ(sg::raw(substrate.diffuse.value), glm::vec3(0.7f, 0.5f, 0.3f));
  EXPECT_EQ(sg::raw(substrate.specular), glm::vec3(0.6f));
  EXPECT_FLOAT_EQ(substrate.alpha, 0.05f);
  auto substrate_error = [&](const std::string& fields) {
    return error(with_camera(R"j("materials": {"m": {"type": "substrate", )j" + fields + "}}"));
  };
  EXPECT_EQ(substrate_error(R"j("diffuse": 0.5, "alpha": 0.1)j"), "test.json: materials.m: missing field 'specular'");
  EXPECT_EQ(substrate_error(R"j("diffuse": 0.5, "specular": 0.5, "alpha": 2)j"),
            "test.json: materials.m.alpha: expected a number in [0.0001, 1], got 2");
  EXPECT_EQ(substrate_error(R"j("diffuse": 0.5, "specular": 0.5, "alpha": 0.1, "ior": 1.5)j"),
            "test.json: materials.m.ior: unknown field (expected one of: type, diffuse, specular, alpha)");
}

// pbrt-v3's translucent, every parameter given (the loader has no defaults);
// seen from outside it scatters at most (diffuse + specular) * (reflect +
// transmit), which must not exceed 1. A texture may stand for the diffuse part.
TEST_F(LoaderFiles, Translucent) {
  Scene scene = load(with_camera(R"j("materials": {
      "t": {"type": "translucent", "diffuse": [0.7, 0.5, 0.3], "specular": 0.2, "reflect": [0.3, 0.4, 0.5],
            "transmit": 0.6, "alpha": 0.05}})j"));
  ASSERT_EQ(scene.materials.size(), 1u);
  const TranslucentMaterial& translucent = std::get<TranslucentMaterial>(scene.materials[0].model);
  EXPECT_EQ(sg::raw(translucent.diffuse.value), glm::vec3(0.7f, 0.5f, 0.3f));
  EXPECT_FALSE(translucent.diffuse.textured());
  EXPECT_EQ(sg::raw(translucent.specular), glm::vec3(0.2f));
  EXPECT_EQ(sg::raw(translucent.reflect), glm::vec3(0.3f, 0.4f, 0.5f));
  EXPECT_EQ(sg::raw(translucent.transmit), glm::vec3(0.6f));
  EXPECT_FLOAT_EQ(translucent.alpha, 0.05f);
  EXPECT_FLOAT_EQ(translucent.ior, 1.5f);  // pbrt-v3's, not a parameter
  auto translucent_error = [&](const std::string& fields) {
    return error(with_camera(R"j("materials": {"m": {"type": "translucent", )j" + fields + "}}"));
  };
  EXPECT_EQ(translucent_error(R"j("diffuse": 0.5, "specular": 0.2, "transmit": 0.5, "alpha": 0.1)j"),
            "test.json: materials.m: missing field 'reflect'");
  EXPECT_EQ(translucent_error(R"j("diffuse": 0.5, "specular": 0.2, "reflect": 0.5, "alpha": 0.1)j"),
            "test.json: materials.m: missing field 'transmit'");
  EXPECT_EQ(translucent_error(R"j("diffuse": 0.5, "specular": 0.2, "reflect": 0.5, "transmit": 1.5, "alpha": 0.1)j"),
            "test.json: materials.m.transmit: reflectance must lie in [0, 1], got 1.5");
  EXPECT_EQ(translucent_error(R"j("diffuse": 0.5, "specular": 0.2, "reflect": 0.5, "transmit": 0.5, "alpha": 0)j"),
            "test.json: materials.m.alpha: expected a number in [0.0001, 1], got 0");
  // 0.8 * (0.7 + 0.6) = 1.04 in the red channel.
  EXPECT_EQ(translucent_error(R"j("diffuse": [0.7, 0.1, 0.1], "specular": 0.1, "reflect": 0.7, "transmit": 0.6, "alpha": 0.1)j"),
            "test.json: materials.m: (diffuse + specular) * (reflect + transmit) must not exceed 1 in any channel "
            "(energy conservation)");
  EXPECT_EQ(translucent_error(R"j("diffuse": 0.5, "specular": 0.2, "reflect": 0.5, "transmit": 0.5, "alpha": 0.1, "ior": 1.3)j"),
            "test.json: materials.m.ior: unknown field (expected one of: type, diffuse, specular, reflect, transmit, alpha)");
}

TEST_F(LoaderFiles, OrenNayar) {
  Scene scene = load(with_camera(R"j("materials": {"clay": {"type": "oren_nayar", "reflectance": 0.6, "sigma": "20 deg"}})j"));
  const OrenNayarMaterial& clay = std::get<OrenNayarMaterial>(scene.materials.at(0).model);
  const double s2 = std::pow(20 * 3.14159265358979 / 180, 2);
  EXPECT_NEAR(clay.a, 1 - s2 / (2 * (s2 + 0.33)), 1e-6);
  EXPECT_NEAR(clay.b, 0.45 * s2 / (s2 + 0.09), 1e-6);
  EXPECT_EQ(error(with_camera(R"j("materials": {"m": {"type": "oren_nayar", "reflectance": 0.6, "sigma": "100 deg"}})j")),
            "test.json: materials.m.sigma: expected an angle in [0 deg, 90 deg], got \"100 deg\"");
  EXPECT_EQ(error(with_camera(R"j("materials": {"m": {"type": "oren_nayar", "reflectance": 0.6, "sigma": 0.3}})j")),
            "test.json: materials.m.sigma: expected angle (e.g. deg), got 0.3 (a number without unit)");
}

// A mix names its parts in any order of the file; it may contain mixes, not itself.
TEST_F(LoaderFiles, Mix) {
  Scene scene = load(with_camera(R"j("materials": {
      "a_mix": {"type": "mix", "first": "paint", "second": "b_mix", "amount": [0.2, 0.5, 0.9]},
      "b_mix": {"type": "mix", "first": "chrome", "second": "paint", "amount": 0.25},
      "chrome": {"type": "mirror", "reflectance": 0.9},
      "paint": {"type": "lambert", "reflectance": 0.5}})j"));
  ASSERT_EQ(scene.materials.size(), 4u);  // in the file's (sorted) order: a_mix, b_mix, chrome, paint
  ASSERT_TRUE(scene.materials[0].mix && scene.materials[1].mix);
  EXPECT_EQ(scene.materials[0].mix->first, 3);
  EXPECT_EQ(scene.materials[0].mix->second, 1);
  EXPECT_EQ(sg::raw(scene.materials[0].mix->amount.value), glm::vec3(0.2f, 0.5f, 0.9f));
  EXPECT_EQ(scene.materials[1].mix->first, 2);
  EXPECT_EQ(scene.materials[1].mix->second, 3);
  auto mix_error = [&](const std::string& materials) { return error(with_camera(R"j("materials": {)j" + materials + "}")); };
  EXPECT_EQ(mix_error(R"j("m": {"type": "mix", "first": "m", "second": "m", "amount": 0.5})j"),
            "test.json: materials.m: mix \"m\" contains itself");
  EXPECT_EQ(mix_error(R"j("m": {"type": "mix", "first": "n", "second": "p", "amount": 0.5},
                          "n": {"type": "mix", "first": "p", "second": "m", "amount": 0.5},
                          "p": {"type": "lambert", "reflectance": 0.5})j"),
            "test.json: materials.n: mix \"n\" contains itself");
  EXPECT_EQ(mix_error(R"j("m": {"type": "mix", "first": "paint", "second": "p", "amount": 0.5},
                          "p": {"type": "lambert", "reflectance": 0.5})j"),
            "test.json: materials.m.first: no material named \"paint\"");
  EXPECT_EQ(mix_error(R"j("m": {"type": "mix", "first": "p", "second": "p", "amount": 1.5},
                          "p": {"type": "lambert", "reflectance": 0.5})j"),
            "test.json: materials.m.amount: reflectance must lie in [0, 1], got 1.5");
  EXPECT_EQ(mix_error(R"j("m": {"type": "mix", "first": "p", "amount": 0.5}, "p": {"type": "lambert", "reflectance": 0.5})j"),
            "test.json: materials.m: missing field 'second'");
}

TEST_F(LoaderFiles, ImageTextures) {
  Scene scene = load(with_camera(R"j("textures": {
      "linear": {"type": "image", "file": "grey.pfm", "filter": "bilinear", "wrap": "clamp", "scale": 0.5,
                 "uv_scale": [4, 2], "uv_offset": [0.5, 0]},
      "painted": {"type": "image", "file": "grey.pfm", "colour_space": "srgb", "scale": 0.5}},
    "materials": {"floor": {"type": "lambert", "reflectance": {"texture": "linear"}},
                  "shiny": {"type": "plastic", "diffuse": {"texture": "painted"}, "specular": 0.04, "alpha": 0.2}})j"));
  ASSERT_EQ(scene.textures.size(), 2u);
  const ImageTexture& linear = scene.textures[0];
  EXPECT_EQ(linear.file, "grey.pfm");
  EXPECT_EQ(linear.colour_space, ColourSpace::linear);  // a PFM holds linear values
  EXPECT_EQ(linear.filter, TextureFilter::bilinear);
  EXPECT_EQ(linear.mipmap->wrap(), TextureWrap::clamp);
  EXPECT_FLOAT_EQ(linear.mapping.u_scale, 4);
  EXPECT_FLOAT_EQ(linear.mapping.v_scale, 2);
  EXPECT_FLOAT_EQ(linear.mapping.u_offset, 0.5f);
  ASSERT_EQ(linear.mipmap->levels(), 2);
  // Rows flipped (t = 0 is the bottom row: 0.5, 1), values times the scale.
  EXPECT_FLOAT_EQ(sg::raw(linear.mipmap->texel(0, 0, 0)).r, 0.25f);
  EXPECT_FLOAT_EQ(sg::raw(linear.mipmap->texel(0, 1, 0)).g, 0.5f);
  EXPECT_FLOAT_EQ(sg::raw(linear.mipmap->texel(0, 0, 1)).b, 0.0f);
  EXPECT_FLOAT_EQ(sg::raw(linear.mipmap->texel(1, 0, 0)).r, (0 + 0.125f + 0.25f + 0.5f) / 4);
  // sRGB-decoded, then scaled: 0.5 encoded is 0.214 linear.
  const ImageTexture& painted = scene.textures[1];
  EXPECT_EQ(painted.colour_space, ColourSpace::srgb);
  EXPECT_NEAR(sg::raw(painted.mipmap->texel(0, 0, 0)).r, 0.5f * 0.2140411f, 1e-6f);
  ASSERT_TRUE(diffuse_of(scene.materials[0]) && diffuse_of(scene.materials[1]));
  EXPECT_EQ(diffuse_of(scene.materials[0])->texture, 0);
  EXPECT_EQ(sg::raw(diffuse_of(scene.materials[0])->value), glm::vec3(1.0f));
  EXPECT_EQ(diffuse_of(scene.materials[1])->texture, 1);

  EXPECT_EQ(error(with_camera(R"j("materials": {"m": {"type": "lambert", "reflectance": {"texture": "wood"}}})j")),
            "test.json: materials.m.reflectance.texture: no texture named \"wood\"");
  EXPECT_EQ(error(with_camera(R"j("textures": {"t": {"type": "image", "file": "grey.pfm", "scale": 2}},
                                   "materials": {"m": {"type": "lambert", "reflectance": {"texture": "t"}}})j")),
            "test.json: materials.m.reflectance.texture: texture \"t\" has values above 1 and cannot be a reflectance (check its scale)");
  EXPECT_EQ(error(with_camera(R"j("textures": {"t": {"type": "image", "file": "grey.pfm"}},
                                   "materials": {"m": {"type": "plastic", "diffuse": {"texture": "t"}, "specular": 0.1, "alpha": 0.1}})j")),
            "test.json: materials.m: diffuse + specular must not exceed 1 in any channel (energy conservation)");
  EXPECT_EQ(error(with_camera(R"j("textures": {"t": {"type": "image", "file": "missing.png"}})j")),
            "test.json: textures.t.file: cannot read image 'missing.png': no such file");
  EXPECT_EQ(error(with_camera(R"j("textures": {"t": {"type": "image", "file": "photo.png"}})j")),
            "test.json: textures.t.file: cannot read image 'photo.png': this program reads PFM images only (no OpenImageIO)");
  EXPECT_EQ(error(with_camera(R"j("textures": {"t": {"type": "image", "file": "grey.pfm", "wrap": "mirror"}})j")),
            "test.json: textures.t.wrap: expected \"repeat\", \"clamp\" or \"black\", got \"mirror\"");
  EXPECT_EQ(error(with_camera(R"j("textures": {"t": {"type": "checkerboard"}})j")),
            "test.json: textures.t.type: expected \"image\", got \"checkerboard\"");
  // A reader that fails names the file and its reason.
  SceneLoadOptions failing{[](const fs::path&) -> Image { throw std::runtime_error("unsupported format"); }};
  try {
    parse_scene(with_camera(R"j("textures": {"t": {"type": "image", "file": "photo.png"}})j"), "test.json", directory_, failing);
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "test.json: textures.t.file: cannot read image 'photo.png': unsupported format");
  }
}

TEST_F(LoaderFiles, TexCoords) {
  Scene scene = load(with_camera(R"j("shapes": [
      {"type": "quad", "origin": ["0 m", "0 m", "0 m"], "edge_u": ["1 m", "0 m", "0 m"], "edge_v": ["0 m", "1 m", "0 m"]},
      {"type": "triangles", "positions": {"value": [[0,0,0],[1,0,0],[0,1,0]], "unit": "m"}, "indices": [0, 1, 2],
       "uvs": [[0, 0], [2, 0], [0, 3]]}])j"));
  ASSERT_EQ(scene.shapes[0].uvs.size(), 4u);
  EXPECT_FLOAT_EQ(scene.shapes[0].uvs[2].u, 1);
  EXPECT_FLOAT_EQ(scene.shapes[0].uvs[2].v, 1);
  ASSERT_EQ(scene.shapes[1].uvs.size(), 3u);
  EXPECT_FLOAT_EQ(scene.shapes[1].uvs[2].v, 3);
  EXPECT_EQ(error(with_camera(R"j("shapes": [{"type": "triangles", "positions": {"value": [[0,0,0],[1,0,0],[0,1,0]], "unit": "m"},
                                             "indices": [0, 1, 2], "uvs": [[0, 0]]}])j")),
            "test.json: shapes[0].uvs: expected one [u, v] per position (3)");
}

TEST_F(LoaderFiles, EnvironmentLight) {
  Scene scene = load(with_camera(R"j("lights": [{"type": "environment", "radiance": "2 W/(m2 sr)"}])j"));
  ASSERT_TRUE(scene.environment);
  EXPECT_FLOAT_EQ(sg::raw(scene.environment->radiance).g, 2.0f);
  EXPECT_FALSE(scene.environment->map);
  EXPECT_TRUE(scene.point_lights.empty());

  scene = load(with_camera(R"j("lights": [{"type": "environment", "file": "grey.pfm",
                                          "transform": [{"rotate": {"axis": [1, 0, 0], "angle": "-90 deg"}}]}])j"));
  ASSERT_TRUE(scene.environment->map);
  EXPECT_FLOAT_EQ(sg::raw(scene.environment->radiance).r, 1.0f);  // the texels are radiance in W/(m2 sr)
  EXPECT_EQ(scene.environment->map->wrap(), TextureWrap::longitude_latitude);
  EXPECT_FLOAT_EQ(sg::raw(scene.environment->map->texel(0, 0, 0)).r, 0.0f);  // not flipped: row 0 is the +z pole
  // Light space +z becomes world +y.
  glm::vec3 pole = sg::raw(scene.environment->render_from_light(direction<LightSpace>(0, 0, 1)));
  EXPECT_NEAR(pole.y, 1.0f, 1e-6f);

  EXPECT_EQ(error(with_camera(R"j("lights": [{"type": "environment"}])j")),
            "test.json: lights[0]: expected 'radiance', 'file' or both");
  EXPECT_EQ(error(with_camera(R"j("lights": [{"type": "environment", "radiance": "1 W/m2"}])j")),
            "test.json: lights[0].radiance: expected radiance (e.g. W/(m2 sr)), got \"1 W/m2\" (irradiance)");
  EXPECT_EQ(error(with_camera(R"j("lights": [{"type": "environment", "radiance": "1 W/(m2 sr)", "transform": [{"translate": ["1 m", "0 m", "0 m"]}]}])j")),
            "test.json: lights[0].transform[0]: an environment light can only be rotated");
  EXPECT_EQ(error(with_camera(R"j("lights": [{"type": "environment", "radiance": "1 W/(m2 sr)"},
                                            {"type": "environment", "radiance": "1 W/(m2 sr)"}])j")),
            "test.json: lights[1]: a scene has at most one environment light");
}

TEST_F(LoaderFiles, PhotonSettings) {
  RenderSettings settings =
      load(with_camera(R"j("render": {"integrator": "photon", "photons": 5000, "photon_radius": "2 cm"})j")).settings;
  EXPECT_EQ(settings.integrator, IntegratorType::photon);
  EXPECT_EQ(settings.photons, 5000);
  EXPECT_FLOAT_EQ(sg::raw(settings.photon_radius), 0.02f);
  EXPECT_EQ(error(with_camera(R"j("render": {"photon_radius": "2 sr"})j")),
            "test.json: render.photon_radius: expected length (e.g. m), got \"2 sr\" (solid angle)");
  EXPECT_EQ(error(with_camera(R"j("render": {"integrator": "bidirectional"})j")),
            "test.json: render.integrator: expected \"direct\", \"path\", \"photon\", \"bdpt\" or \"sppm\", got \"bidirectional\"");
}

}  // namespace
}  // namespace safegi::render
