// A loaded scene: every physical value already in reference units (m, s, J,
// rad, sr) and every geometric value tagged with the space it lives in.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "safegi/cpu_renderer/quoted_list.hpp"
#include "safegi/cpu_renderer/procedural_texture.hpp"
#include "safegi/cpu_renderer/texture.hpp"
#include "safegi/cpu_renderer/types.hpp"

namespace safegi::render {

// An image texture: a MIP pyramid of linear texels and how surface (u, v)
// reach it. Reflectance textures are dimensionless; (0, 0) is the image's
// bottom-left corner (the loader flips the file's rows, as pbrt does).
struct ImageTexture {
  std::string name;
  std::string file;                              // as written in the scene (for messages)
  ColourSpace colour_space = ColourSpace::srgb;  // how the file encoded its values (decoded at load)
  TextureFilter filter = TextureFilter::trilinear;
  Real max_anisotropy = 8;  // ewa: the ellipse's longest major/minor ratio (pbrt-v3's "maxanisotropy")
  Real scale = 1.0f;  // multiplies every texel (pbrt's "scale")
  Mapping2D mapping;  // the surface point to the lookup's (s, t)
  std::shared_ptr<const MipMap> mipmap;  // built once at load, wrap mode included
};

// A reflectance that may be textured: `value` times the texture's texel, or
// times the pattern's value (at most one of the two).
struct TexturedReflectance {
  Reflectance value{};
  int texture = -1;  // index into Scene::textures (images); -1: none
  int pattern = -1;  // index into Scene::patterns (procedural); -1: none
  bool textured() const { return texture >= 0 || pattern >= 0; }
};

// One parameter type per material: each holds only what its BSDF reads, and a
// std::visit over Material::model makes the compiler list every place that
// must learn a new one.
struct LambertMaterial {
  TexturedReflectance diffuse;  // the albedo
};
// Oren and Nayar's rough diffuse surface, pbrt-v3's OrenNayar: facets whose
// slopes have standard deviation σ, f = ρ/π (A + B max(0, cos(φi − φo)) sin α
// tan β), α = max(θi, θo), β = min(θi, θo); A = 1 − σ²/(2(σ² + 0.33)), B =
// 0.45 σ²/(σ² + 0.09), σ in radians. σ = 0 is Lambert.
struct OrenNayarMaterial {
  TexturedReflectance diffuse;
  Real a = 1.0f, b = 0.0f;
  static OrenNayarMaterial with_sigma(const TexturedReflectance& diffuse, Angle sigma) {
    const Real s = sg::raw(sigma / units::radian), s2 = s * s;
    return {diffuse, 1 - s2 / (2 * (s2 + Real(0.33))), Real(0.45) * s2 / (s2 + Real(0.09))};
  }
};
struct PhongMaterial {  // energy-conserving Phong (Lafortune & Willems)
  TexturedReflectance diffuse;
  Reflectance specular{};
  Real exponent = 1.0f;  // the lobe's cosine power (dimensionless)
};
struct PlasticMaterial {  // pbrt's plastic: Lambert plus a Fresnel-weighted Trowbridge–Reitz lobe
  TexturedReflectance diffuse;
  Reflectance specular{};  // pbrt's Ks
  Real alpha = 0.0f;       // the lobe's GGX roughness alpha; 0 = smooth
  Real ior = 1.5f;         // the coating's index of refraction inside over outside
  // pbrt-v3's plastic evaluates its Fresnel term as FrDielectric(cos, 1.5, 1), the
  // indices swapped (mmp/pbrt-v3#210, left unfixed there); true reproduces that.
  bool pbrt_v3_fresnel = false;
};
struct MirrorMaterial {
  Reflectance reflectance{};  // the tint of the perfect reflection
};
struct GlassMaterial {  // smooth dielectric
  Reflectance reflectance{};    // the tint of Fresnel reflection (pbrt's Kr)
  Reflectance transmittance{};  // the tint of refraction (pbrt's Kt)
  Real ior = 1.5f;              // index of refraction inside over outside
};
// A rough metal (pbrt-v3's metal, pbrt-v4's conductor): the conductor's Fresnel
// reflectance at the microfacet times a Trowbridge–Reitz lobe; nothing enters.
struct ConductorMaterial {
  IndexSpectrum eta{};  // the metal's index over the outside's, real part η (> 0), per channel
  IndexSpectrum k{};    // the extinction coefficient k (>= 0): the index's imaginary part
  Real alpha = 0.001f;  // the lobe's GGX roughness alpha (pbrt-v3's floor: 0.001)
};
// pbrt-v3's substrate: Ashikhmin and Shirley's FresnelBlend, a diffuse base
// under a glossy coat whose Schlick Fresnel term takes what the base gets
// (the base is weighted by 1 − ρs), so ρd + ρs above 1 gains no energy, unlike
// plastic's sum. Sampled half and half as pbrt-v3 does, not by the two parts'
// sizes: the Bsdf does not give it plastic's lobe choice.
struct SubstrateMaterial {
  TexturedReflectance diffuse;  // pbrt's Kd
  Reflectance specular{};       // pbrt's Ks: the coat's reflectance at normal incidence
  Real alpha = 0.001f;          // the coat's GGX roughness alpha (pbrt-v3's floor: 0.001)
};
// pbrt-v3's translucent: a surface that scatters to both sides, Lambert's
// and a rough dielectric interface's (Trowbridge–Reitz; index 1.5 on the side
// the geometric normal points away from, as glass's inside), each lobe
// weighted by `reflect` or `transmit`: reflect·Kd and transmit·Kd diffusely,
// reflect·Ks·F and transmit·Ks·(1 − F) through the microfacets. Sampled as
// pbrt-v3 samples it: one of its non-black lobes, each as likely.
struct TranslucentMaterial {
  TexturedReflectance diffuse;  // pbrt's Kd
  Reflectance specular{};       // pbrt's Ks
  Reflectance reflect{};        // the share of either part that goes back
  Reflectance transmit{};       // the share of either part that goes through
  Real alpha = 0.001f;          // the microfacets' GGX roughness alpha (pbrt-v3's floor: 0.001)
  Real ior = 1.5f;              // the interface's index, inside over outside (pbrt-v3 fixes 1.5)
};
// pbrt-v3's disney without subsurface scattering: Burley's diffuse,
// retro-reflection and sheen, an anisotropic GGX specular lobe with pbrt-v3's
// DisneyFresnel, a GTR1 clearcoat and rough specular transmission; a thin
// one blends the diffuse with a fake subsurface lobe (flatness) and lets
// some through diffusely (difftrans) (disney.hpp). Each weight lies in [0, 1],
// as pbrt-v3's parameters of the same names.
struct DisneyMaterial {
  TexturedReflectance diffuse;  // pbrt's "color", the base colour (diffuse_of's: a texture applies to it)
  Real metallic = 0;
  Real eta = 1.5f;  // the interface's index, inside over outside
  Real roughness = 0.5f;
  Real specular_tint = 0;
  Real anisotropic = 0;  // along the shading frame's x and y
  Real sheen = 0;
  Real sheen_tint = 0.5f;
  Real clearcoat = 0;
  Real clearcoat_gloss = 1;
  Real spec_trans = 0;
  bool thin = false;
  Real flatness = 0;    // thin: the fake subsurface lobe's share of the diffuse one
  Real diff_trans = 1;  // thin: twice the share of the diffuse light transmitted (pbrt-v3 halves it)
};
struct BlackMaterial {};  // absorbs everything

using MaterialModel = std::variant<BlackMaterial, LambertMaterial, PhongMaterial, PlasticMaterial, MirrorMaterial,
                                   GlassMaterial, ConductorMaterial, SubstrateMaterial, TranslucentMaterial,
                                   OrenNayarMaterial, DisneyMaterial>;

// pbrt-v3's bump map: the surface displaced along its normal by `scale` times
// the luminance of an image texture at (u, v), or a float pattern's value at
// the hit. Only the shading normal changes (the normal of the displaced
// surface); rays still leave the real one.
struct BumpMap {
  int texture = -1;         // index into Scene::textures, or -1 and
  int pattern = -1;         // index into Scene::patterns
  Length scale = sg::zero;  // the displacement per unit of the texture's value
};

// pbrt-v3's MixMaterial: the first material's BSDF weighted by `amount` and
// the second's by 1 − amount, per channel. Not a BSDF of its own: each hit
// picks one of the two (material_mix.hpp), as pbrt-v4 does.
struct MaterialMix {
  int first = -1, second = -1;  // indices into Scene::materials; -1: black (absorbs)
  TexturedReflectance amount;   // in [0, 1]
};

struct Material {
  MaterialModel model;  // unused where `mix` is set
  std::string name;
  std::optional<BumpMap> bump;
  std::optional<MaterialMix> mix;
};

// The diffuse part of a material that has one (Lambert, Phong, plastic, substrate, translucent), else nullptr.
inline const TexturedReflectance* diffuse_of(const Material& material) {
  return std::visit(
      [](const auto& model) -> const TexturedReflectance* {
        if constexpr (requires { model.diffuse; })
          return &model.diffuse;
        else
          return nullptr;
      },
      material.model);
}

// Perfect mirrors and smooth glass: no density over directions.
inline bool is_specular(const MaterialModel& model) {
  return std::holds_alternative<MirrorMaterial>(model) || std::holds_alternative<GlassMaterial>(model);
}

// The visitor of one lambda per material type, for std::visit over a MaterialModel.
template <class... Lambdas>
struct Overloaded : Lambdas... {
  using Lambdas::operator()...;
};
// Clang 14 does not deduce an aggregate's template arguments (C++20's P1816).
template <class... Lambdas>
Overloaded(Lambdas...) -> Overloaded<Lambdas...>;

// Surface parameters of a mesh vertex (dimensionless), for texture lookups.
struct TexCoord {
  Real u = 0.0f, v = 0.0f;
};

// The media a shape separates (indices into Scene::media; -1: vacuum). As in
// pbrt-v3, "outside" is the side the geometric normal points to.
struct MediumInterface {
  int inside = -1;
  int outside = -1;
};

// A homogeneous participating medium (pbrt-v3's "homogeneous"): light is
// absorbed and scattered at rates per length, and scatters by
// Henyey–Greenstein's phase function of asymmetry g.
struct Medium {
  std::string name;
  spectrum<dim::inv_length> absorption;  // σa
  spectrum<dim::inv_length> scattering;  // σs
  Real asymmetry = 0;                    // g, in (-1, 1): > 0 scatters forwards
  spectrum<dim::inv_length> extinction() const { return absorption + scattering; }  // σt
};

struct Shape {
  enum class Type { mesh, sphere };
  Type type = Type::mesh;
  std::string name;
  // mesh: triangles over positions in object space
  std::vector<PointObject> positions;
  std::vector<uint32_t> indices;
  std::vector<TexCoord> uvs;  // empty, or one per position (absent: each triangle's (0,0), (1,0), (1,1))
  // Empty, or one per position: pbrt-v3's "N", interpolated across each
  // triangle as the shading normal (the geometric one still decides sides).
  std::vector<normal<Object>> normals;
  // sphere, in object space
  PointObject center;
  Length radius = sg::zero;

  int material = -1;  // index into Scene::materials; -1: absorbs everything
  // No surface at all (pbrt-v3's material "" or "none"): rays pass through it,
  // which only matters where it bounds a participating medium (or emits).
  bool invisible = false;
  // An invisible surface that still stops the light sent to a scattering
  // point: shadow rays, and emission that a scattered ray finds beyond it
  // (camera rays and the paths go on through it). pbrt-v3's integrators
  // without media (path, directlighting, whitted) test shadow rays against
  // every surface, so an emitter of material "none" hides its own far side.
  bool occludes_light = false;
  // pbrt-v3's alpha masks (on triangle meshes): where `alpha` is exactly 0 the
  // surface is not there for any ray; where `shadow_alpha` is, it casts no
  // shadow. A mask's first channel counts (float textures are grey here).
  std::optional<TexturedReflectance> alpha, shadow_alpha;
  // The media on either side, where they differ (absent: the side a ray is on
  // is whatever medium it was already in).
  std::optional<MediumInterface> media;
  std::optional<Radiance> emission;
  bool two_sided_emission = false;
  int emission_samples = 1;  // an emitter's shadow rays per shading point with LightStrategy::all (pbrt's nsamples)

  RenderFromObject render_from_object;
  // Rigid motion: where the object is at shutter close (absent: static).
  std::optional<RenderFromObject> render_from_object_at_close;
};

// A sphere's radius after `render_from_object` (which scales a sphere uniformly).
inline Length placed_radius(const RenderFromObject& render_from_object, Length radius) {
  return sg::length(render_from_object(vector<Object>(radius, sg::zero, sg::zero)));
}

// What shapes a point light's intensity by direction, as pbrt-v3's
// goniometric and projection lights do: towards ω the light sends its
// intensity times the texel at ω's place on the map (in light space, a
// rotation of render space).
//   goniometric: a lat-long map around light space's +y (pbrt-v3 swaps y and
//     z): s = φ/2π with φ = atan2(z, x), t = θ/π with θ from +y; row 0 is θ = 0.
//   projection: the image through a frustum along +z whose shorter image axis
//     spans `fov`: (x/z, y/z) on the plane z = 1 over the window ±tan(fov/2)
//     times the image's aspect, t growing with y (row 0 at −y, as in pbrt-v3);
//     nothing outside it or behind the light. Without a map the window is square.
struct IntensityMap {
  enum class Layout { goniometric, projection } layout = Layout::goniometric;
  std::string file;                   // as written in the scene; empty: no map (texels of 1)
  std::shared_ptr<const MipMap> map;
  RenderFromLight render_from_light;  // a rotation
  Angle fov = sg::zero;               // projection
};

// The map's factor on the intensity towards `towards` (a unit vector from the light).
Texel intensity_factor(const IntensityMap& map, DirectionWorld towards);
// The factor's mean over the sphere of directions (pbrt-v3's Power: for
// choosing among lights and for the preview's stand-in).
Texel mean_intensity_factor(const IntensityMap& map);

struct PointLight {
  PointWorld position;
  Intensity intensity;
  std::optional<IntensityMap> profile;  // absent: the same intensity every way
};

// A spot light as pbrt-v3 defines it: intensity I (on its axis) times a
// falloff of the angle θ to the axis — 1 up to cone_angle − cone_delta, then
// δ⁴ with δ = (cos θ − cos cone_angle) / (cos(cone_angle − cone_delta) − cos cone_angle),
// and 0 beyond cone_angle.
struct SpotLight {
  PointWorld position;
  DirectionWorld direction;
  Intensity intensity;
  Angle cone_angle = sg::zero;
  Angle cone_delta = sg::zero;
};

// The spot's falloff towards a direction at cos θ to its axis.
inline Real spot_falloff(const SpotLight& light, Real cos_theta) {
  Real cos_total = sg::cos(light.cone_angle), cos_start = sg::cos(light.cone_angle - light.cone_delta);
  if (cos_theta < cos_total) return 0;
  if (cos_theta >= cos_start) return 1;
  Real delta = (cos_theta - cos_total) / (cos_start - cos_total);
  return (delta * delta) * (delta * delta);
}

// Light from one direction, as from a sun infinitely far away (pbrt-v3's
// distant light): `irradiance` on a surface facing it, `irradiance` · cos θ on
// one tilted by θ, the same everywhere it is not in shadow.
struct DistantLight {
  DirectionWorld direction;  // towards the light
  spectrum<dim::irradiance> irradiance;
};

// Light from infinitely far away in every direction. Without a map its
// radiance is constant; with one (lat-long, linear RGB, pbrt's layout) the
// radiance towards -w is `radiance` times the texel at u = φ/2π, v = θ/π, where
// θ is measured from light space's +z and φ = atan2(y, x); row 0 is θ = 0.
struct EnvironmentLight {
  Radiance radiance;                  // constant radiance, or the factor on the map's texels
  std::string file;                   // the map, as written in the scene; empty: constant
  std::shared_ptr<const MipMap> map;  // lat-long texels (u wraps, v clamps)
  RenderFromLight render_from_light;     // a rotation
  int samples = 1;                       // shadow rays per shading point with LightStrategy::all (pbrt's nsamples)
};

// How the camera maps the image to rays (pbrt-v3's cameras of those names):
// through a pinhole or thin lens; parallel, from an image-sized window;
// every direction around the position, longitude across and latitude down.
enum class CameraProjection { perspective, orthographic, environment };

struct Camera {
  CameraProjection projection = CameraProjection::perspective;
  PointWorld position;
  PointWorld look_at;
  DirectionWorld up;
  Angle fov = sg::zero;  // perspective: across the shorter image axis
  Length view_size = sg::zero;  // orthographic: the shorter image axis's extent across the scene
  Length lens_radius = sg::zero;
  Length focus_distance = sg::zero;
  Time shutter_open = sg::zero;
  Time shutter_close = sg::zero;
  int medium = -1;  // the medium the camera is in (index into Scene::media; -1: vacuum)
};

enum class IntegratorType { direct, path, photon, bdpt, sppm };

// How next-event estimation picks the lights its shadow rays go to (pbrt-v3's
// strategies of those names): one light per shadow ray, in proportion to
// power, uniformly, or by the lights' estimated contributions to the shading
// point's part of the scene (spatial); or every light, each with its own
// number of shadow rays (all: pbrt-v3's directlighting). Only the noise differs.
enum class LightStrategy { power, uniform, spatial, all };
// The most shadow rays one light takes per shading point with `all`.
inline constexpr int kMaxEmitterSamples = 4096;
inline constexpr const char* kLightStrategyNames[] = {"power", "uniform", "spatial", "all"};
inline const char* name_of(LightStrategy strategy) { return kLightStrategyNames[static_cast<int>(strategy)]; }
// The enumerator whose name (in `names`, in the enumeration's order) is `name`.
template <class Enum, size_t N>
std::optional<Enum> enum_named(const char* const (&names)[N], std::string_view name) {
  for (size_t i = 0; i < N; ++i)
    if (name == names[i]) return static_cast<Enum>(i);
  return std::nullopt;
}
// The names quoted, as a message lists the choices: "a", "b" or "c".
template <size_t N>
std::string quoted_choices(const char* const (&names)[N]) {
  return quoted_list(names);
}
inline std::optional<LightStrategy> light_strategy_named(std::string_view name) {
  return enum_named<LightStrategy>(kLightStrategyNames, name);
}

// The widest and tallest image a scene file or a command line may ask for.
inline constexpr int kMaxImageSide = 65536;

// How samples make pixels (pbrt-v3's pixel filters, each a product of one
// function per axis, radii in pixels): a box one pixel wide is each pixel's
// mean; the others weigh samples by their offset from the pixel's centre and
// reach into the neighbours' area (pixel_filter.hpp).
enum class PixelFilterType { box, triangle, gaussian, mitchell, sinc };
inline constexpr const char* kPixelFilterNames[] = {"box", "triangle", "gaussian", "mitchell", "sinc"};
// How samples make pixels under a filter. sample (pbrt-v4's way): each
// sample's offset is drawn from the filter and it stays in its own pixel.
// splat (pbrt-v3's Film::AddSample): each sample, uniform in its pixel, adds
// f·L and f to every pixel whose centre is within the filter's radius. Both
// converge to the same filtered image; a splatted pixel averages the samples
// of its neighbours too (lower noise in smooth regions, neighbours correlated).
enum class PixelFilterMode { sample, splat };
inline constexpr const char* kPixelFilterModeNames[] = {"sample", "splat"};
inline std::optional<PixelFilterMode> pixel_filter_mode_named(std::string_view name) {
  return enum_named<PixelFilterMode>(kPixelFilterModeNames, name);
}
struct PixelFilter {
  PixelFilterType type = PixelFilterType::box;
  PixelFilterMode mode = PixelFilterMode::sample;
  double radius_x = 0.5, radius_y = 0.5;
  double gaussian_alpha = 2;                     // exp(−α x²), less its value at the radius
  double mitchell_b = 1.0 / 3, mitchell_c = 1.0 / 3;
  double sinc_tau = 3;                           // sinc(x) · sinc(x / τ) (Lanczos)
};
inline std::optional<PixelFilterType> pixel_filter_named(std::string_view name) {
  return enum_named<PixelFilterType>(kPixelFilterNames, name);
}
inline constexpr double kMinFilterRadius = 1e-3, kMaxFilterRadius = 64;  // pixels, both scene formats
// pbrt-v3's default radius of each filter, in pixels.
inline double default_filter_radius(PixelFilterType type) {
  return type == PixelFilterType::box ? 0.5 : type == PixelFilterType::sinc ? 4 : 2;
}

struct RenderSettings {
  int width = 256;
  int height = 256;
  int spp = 16;
  int max_depth = 65;
  IntegratorType integrator = IntegratorType::path;
  // Knobs of the speed/accuracy study; every combination is unbiased.
  bool mis = true;                 // off: area lights by light sampling only (BSDF rays ignore their emission)
  int light_samples = 1;           // shadow rays per shading point for direct lighting (rounds of them, with `all`)
  LightStrategy light_strategy = LightStrategy::power;
  PixelFilter filter;
  bool russian_roulette = true;    // off: paths end only at max_depth or when nothing is hit
  int russian_roulette_depth = 3;  // bounces before Russian roulette starts
  // Photon mapping (integrator photon): photons traced from the lights, and the
  // radius of the density estimate (zero: chosen from the scene's size).
  int photons = 200000;
  Length photon_radius = sg::zero;
  // Stochastic progressive photon mapping (integrator sppm, sppm.hpp):
  // iterations, photons per iteration (not positive: the film's pixels) and
  // the initial radius of the visible points (zero: one metre).
  int sppm_iterations = 64;
  int sppm_photons_per_iteration = -1;
  Length sppm_radius = sg::zero;
  // Every pixel of the finished image times this (pbrt-v3's Film "scale").
  double film_scale = 1;
};

struct Scene {
  RenderSettings settings;
  Camera camera;
  std::vector<ImageTexture> textures;
  std::vector<ProceduralTexture> patterns;
  std::vector<Material> materials;
  std::vector<Shape> shapes;
  std::vector<PointLight> point_lights;
  std::vector<SpotLight> spot_lights;
  std::vector<DistantLight> distant_lights;
  std::optional<EnvironmentLight> environment;
  std::vector<Medium> media;

  // Hits need their surface detail (texture coordinates, bumps, interpolated normals).
  bool textured() const {
    if (!textures.empty() || !patterns.empty()) return true;
    for (const Shape& shape : shapes)
      if (!shape.normals.empty()) return true;
    return false;
  }
  // Rays must track media and cross invisible boundaries.
  bool has_media() const {
    if (!media.empty()) return true;
    for (const Shape& shape : shapes)
      if (shape.invisible) return true;
    return false;
  }
  // The scene in vacuum: no media, and no invisible surface that emits nothing
  // (it would change no ray), as pbrt-v3's integrators without media render it.
  void drop_media() {
    camera.medium = -1;
    media.clear();
    for (Shape& shape : shapes) shape.media.reset();
    std::erase_if(shapes, [](const Shape& shape) { return shape.invisible && !shape.emission; });
  }
};

}  // namespace safegi::render
