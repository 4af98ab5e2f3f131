// pbrt-v3's texture mappings and procedural textures (its textures/
// checkerboard, dots, fbm, wrinkled, windy, marble, uv and bilerp) as Scene
// patterns.
#include <cmath>

#include "pbrt/pbrt_importer.hpp"

namespace safegi::render::pbrt {
namespace {

// A parameter of a pattern: finite and within [low, high] (pbrt-v3 reads any
// number; beyond these the noise sums overflow or lose every digit).
double bounded(ParamSet& params, const char* name, double fallback, double low, double high) {
  double value = params.one_float(name, fallback);
  if (!(value >= low && value <= high)) {
    params.fail_at(*params.find(name, {ParamType::floating, ParamType::texture}),
                   "\"float " + std::string(name) + "\" of " + params.context() + " must lie in [" + format_number(low) +
                       ", " + format_number(high) + "], found " + format_number(value));
  }
  return value;
}

}  // namespace

// pbrt-v3's TextureMapping2D as its textures read it ("mapping", default "uv").
Mapping2D Importer::mapping_2d(ParamSet& params, SourceRange at) {
  auto number = [&](const char* parameter, double fallback) {
    double value = params.one_float(parameter, fallback);
    if (!(std::fabs(value) <= 1e6))
      fail(at, "\"float " + std::string(parameter) + "\" of " + params.context() + " must lie in [-1e6, 1e6]");
    return static_cast<Real>(value);
  };
  Mapping2D result;
  const std::string kind = params.one_string("mapping", "uv");
  if (kind == "uv") {
    result.u_scale = number("uscale", 1);
    result.v_scale = number("vscale", 1);
  } else if (kind == "spherical" || kind == "cylindrical") {
    result.kind = kind == "spherical" ? Mapping2D::Kind::spherical : Mapping2D::Kind::cylindrical;
    result.space = solid_mapping(at);  // pbrt-v3's WorldToTexture: the inverse of the transform at the Texture
    return result;
  } else if (kind == "planar") {
    result.kind = Mapping2D::Kind::planar;
    result.space = solid_mapping(at, false);  // pbrt-v3 reads the point in its world
    auto axis = [&](const char* parameter, Triple fallback) {
      const Triple given = params.one_vector(parameter).value_or(fallback);
      const glm::dvec3 v(given[0], given[1], given[2]);
      if (!(glm::length(v) <= 1e6))
        fail(at, "\"vector " + std::string(parameter) + "\" of " + params.context() + " must lie within 1e6 of 0");
      return sg::vec3_rep(v);
    };
    result.s_axis = axis("v1", {1, 0, 0});
    result.t_axis = axis("v2", {0, 1, 0});
  } else {
    params.fail_at(*params.find("mapping", {ParamType::string}), "texture mapping \"" + kind + "\" is unknown",
                   "pbrt-v3 has \"uv\", \"spherical\", \"cylindrical\" and \"planar\" (and would use \"uv\")");
  }
  result.u_offset = number("udelta", 0);
  result.v_offset = number("vdelta", 0);
  return result;
}

// pbrt-v3's IdentityMapping3D: a point in the space the transform stood for
// at the Texture directive (or, `in_texture_space` false, in pbrt's world), in
// the scene file's length unit.
SolidMapping Importer::solid_mapping(SourceRange at, bool in_texture_space) {
  const Matrix texture_from_pbrt_world = in_texture_space ? glm::inverse(state_.transform.start) : Matrix(1.0);
  if (in_texture_space && !std::isnormal(glm::determinant(state_.transform.start)))
    fail(at, "the transform in effect at this Texture is singular", "pbrt-v3 maps points into texture space by its inverse");
  // From our world (metres) to pbrt's world, then to texture space: pbrt units.
  const Matrix texture_from_render_units = texture_from_pbrt_world * glm::inverse(world_from_pbrt_world_);
  const double unit = options_.metres_per_unit;
  const Matrix texture_from_render = Matrix(glm::dmat3(unit)) * texture_from_render_units;  // the same, in metres
  SolidMapping mapping;
  mapping.texture_from_render = sg::from_raw<TextureFromRender>(
      sg::matrix_pair{sg::mat4_rep(texture_from_render), sg::mat4_rep(glm::inverse(texture_from_render))});
  mapping.unit = static_cast<Real>(unit) * units::metre;
  mapping.stretch = static_cast<Real>(unit * std::cbrt(std::abs(glm::determinant(glm::dmat3(texture_from_render_units)))));
  return mapping;
}

// One of a pattern's two values: a colour (or a constant texture) in [0, 1];
// of a float texture, a number (a displacement: any finite one), grey.
Reflectance Importer::pattern_colour(ParamSet& params, const char* name, double fallback, bool spectrum) {
  const Param* param = nullptr;
  std::optional<TextureEntry> given = spectrum ? spectrum_or_texture(params, name, param) : float_or_texture(params, name, param);
  if (!given) return sg::from_raw<Reflectance>(sg::vec3_rep(static_cast<Real>(fallback)));
  if (given->textured())
    params.fail_at(*param, "a texture as \"" + std::string(name) + "\" of " + params.context() + " is not supported",
                   spectrum ? "give it as a colour (\"rgb " + std::string(name) + "\" [r g b])"
                            : "give it as a number (\"float " + std::string(name) + "\" 0.5)");
  for (double c : given->value) {
    if (spectrum && !(c >= 0 && c <= 1))
      params.fail_at(*param, "\"" + std::string(name) + "\" of " + params.context() + " must lie in [0, 1] in every channel",
                     "above 1 a surface reflects more light than it receives");
    if (!spectrum && !(std::fabs(c) <= 1e6))
      params.fail_at(*param, "\"" + std::string(name) + "\" of " + params.context() + " must lie in [-1e6, 1e6]");
  }
  return sg::from_raw<Reflectance>(sg::vec3_rep(static_cast<Real>(given->value[0]), static_cast<Real>(given->value[1]),
                                                static_cast<Real>(given->value[2])));
}

std::optional<Pattern> Importer::pattern(const std::string& texture_class, ParamSet& params, SourceRange at, bool spectrum) {
  auto value = [&](const char* name, double fallback) { return pattern_colour(params, name, fallback, spectrum); };
  auto octaves = [&] { return params.one_int("octaves", 8, 0, 32); };
  auto roughness = [&] { return static_cast<Real>(bounded(params, "roughness", 0.5, 0, 16)); };
  if (texture_class == "checkerboard") {
    const int dimension = params.one_int("dimension", 2, 2, 3);
    if (dimension == 3) return SolidCheckerboardPattern{solid_mapping(at), value("tex1", 1), value("tex2", 0)};
    CheckerboardPattern board{mapping_2d(params, at), value("tex1", 1), value("tex2", 0)};
    std::string mode = params.one_string("aamode", "closedform");
    board.box_filtered = mode != "none";
    if (mode != "none" && mode != "closedform")
      warn(params.find("aamode", {ParamType::string})->values, "antialiasing mode \"" + mode + "\" is unknown: using \"closedform\"",
           "pbrt-v3 does the same");
    return board;
  }
  if (texture_class == "dots") {
    // pbrt-v3's CreateDots*Texture pass "inside" and "outside" to a constructor
    // that takes (outsideDot, insideDot): its dots show "outside", the rest
    // "inside". Swapped here too, so that scenes render as pbrt-v3 renders them.
    Reflectance inside = value("inside", 1), outside = value("outside", 0);
    return DotsPattern{mapping_2d(params, at), outside, inside};
  }
  if (texture_class == "fbm" || texture_class == "wrinkled")
    return FbmPattern{solid_mapping(at), roughness(), octaves(), texture_class == "wrinkled"};
  if (texture_class == "windy") return WindyPattern{solid_mapping(at)};
  if (texture_class == "uv" && spectrum) return UvPattern{mapping_2d(params, at)};  // pbrt-v3 has no float one
  if (texture_class == "bilerp")
    return BilerpPattern{mapping_2d(params, at), value("v00", 0), value("v01", 1), value("v10", 0), value("v11", 1)};
  if (texture_class == "marble") {
    MarblePattern marble{solid_mapping(at)};
    marble.octaves = octaves();
    marble.omega = roughness();
    marble.scale = static_cast<Real>(bounded(params, "scale", 1, -1e6, 1e6));
    marble.variation = static_cast<Real>(bounded(params, "variation", 0.2, -1e6, 1e6));
    return marble;
  }
  return std::nullopt;
}

}  // namespace safegi::render::pbrt
