// The importer's state machine, transforms and options block (camera, film,
// sampler, integrator, filter), and the public entry points. The world block's
// materials, shapes and lights are in pbrt_world.cpp.
#include "pbrt/pbrt_importer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numbers>
#include <sstream>
#include <string_view>

#include <safegi/diagnostics/render.hpp>

#include "safegi/cpu_renderer/unit_expression.hpp"

namespace safegi::render {

namespace pbrt {

namespace {

constexpr double kDegree = std::numbers::pi / 180;

Matrix translate(glm::dvec3 d) {
  Matrix m(1.0);
  m[3] = glm::dvec4(d, 1.0);
  return m;
}

Matrix scale(glm::dvec3 s) {
  Matrix m(1.0);
  m[0][0] = s.x, m[1][1] = s.y, m[2][2] = s.z;
  return m;
}

// pbrt-v3's Rotate(theta, axis) (core/transform.cpp), angle in degrees.
Matrix rotate(double degrees, glm::dvec3 axis) {
  glm::dvec3 a = glm::normalize(axis);
  double s = std::sin(degrees * kDegree), c = std::cos(degrees * kDegree);
  double r[3][3] = {{a.x * a.x + (1 - a.x * a.x) * c, a.x * a.y * (1 - c) - a.z * s, a.x * a.z * (1 - c) + a.y * s},
                    {a.x * a.y * (1 - c) + a.z * s, a.y * a.y + (1 - a.y * a.y) * c, a.y * a.z * (1 - c) - a.x * s},
                    {a.x * a.z * (1 - c) - a.y * s, a.y * a.z * (1 - c) + a.x * s, a.z * a.z + (1 - a.z * a.z) * c}};
  Matrix m(1.0);
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) m[col][row] = r[row][col];
  return m;
}

// Transform [ ... ]: pbrt-v3 reads the 16 numbers column by column.
Matrix from_numbers(const std::vector<double>& v) {
  Matrix m;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m[c][r] = v[4 * c + r];
  return m;
}

bool finite(const Matrix& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

// pbrt-v3 uses transforms only through their inverses too: a singular one has none.
bool invertible(const Matrix& m) {
  double det = glm::determinant(m);
  return std::isnormal(det) && finite(glm::inverse(m));
}

SourceRange span(const Directive& d) {
  return d.arguments.begin.file == d.range.begin.file ? SourceRange{d.range.begin, d.arguments.end} : d.range;
}

// Shape of the directive table below: which block a directive belongs to.
enum class Where { anywhere, options, world };
struct DirectiveRule {
  std::string_view name;
  Where where;
};
constexpr DirectiveRule kRules[] = {
    {"Identity", Where::anywhere},         {"Translate", Where::anywhere},        {"Scale", Where::anywhere},
    {"Rotate", Where::anywhere},           {"LookAt", Where::anywhere},           {"Transform", Where::anywhere},
    {"ConcatTransform", Where::anywhere},  {"CoordinateSystem", Where::anywhere}, {"CoordSysTransform", Where::anywhere},
    {"ActiveTransform", Where::anywhere},  {"MediumInterface", Where::anywhere},  {"MakeNamedMedium", Where::anywhere},
    {"TransformTimes", Where::options},    {"Camera", Where::options},            {"Film", Where::options},
    {"Sampler", Where::options},           {"Integrator", Where::options},        {"PixelFilter", Where::options},
    {"Accelerator", Where::options},       {"WorldBegin", Where::options},
};

// pbrt-v3's integrators that we do not have, and the nearest one we do: the
// same image in expectation (all are unbiased or consistent estimators of the
// same light transport), with other noise.
struct IntegratorSubstitute {
  std::string_view pbrt;
  IntegratorType ours;
  std::string_view ours_name;
  std::string_view why;
  std::array<std::string_view, 6> noise_only;  // its parameters that change the noise only (empty names pad)
};
constexpr IntegratorSubstitute kIntegratorSubstitutes[] = {
    {"mlt", IntegratorType::bdpt, "bdpt",
     "bdpt converges to the same image; MLT's Metropolis sampling of bdpt's paths only spreads its noise differently",
     {"bootstrapsamples", "chains", "mutationsperpixel", "largestepprobability", "sigma"}},
};

const IntegratorSubstitute* substitute_for(const std::string& type) {
  for (const IntegratorSubstitute& substitute : kIntegratorSubstitutes)
    if (substitute.pbrt == type) return &substitute;
  return nullptr;
}

}  // namespace

// How far a linear map is from a uniformly scaled rotation or mirroring: the
// largest entry of FᵀF/s² − I, s² the mean squared column length (0 for a
// similarity; cosines between columns and relative differences of squared lengths).
double deviation_from_similarity(const glm::dmat3& f) {
  const glm::dmat3 gram = glm::transpose(f) * f;
  const double mean_square = (gram[0][0] + gram[1][1] + gram[2][2]) / 3;
  // A map that collapses space (or overflows) is no similarity at all.
  if (!(mean_square > 0) || !std::isfinite(mean_square)) return std::numeric_limits<double>::infinity();
  double deviation = 0;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) deviation = std::max(deviation, std::fabs(gram[c][r] / mean_square - (r == c ? 1 : 0)));
  return deviation;
}

// The similarity nearest an invertible map: its orthogonal polar factor
// (Newton's iteration R ← (R + R⁻ᵀ)/2, which keeps the determinant's sign)
// times the cube root of |det|, the scale that keeps its volume.
glm::dmat3 nearest_similarity(const glm::dmat3& f) {
  const double scale = std::cbrt(std::fabs(glm::determinant(f)));
  glm::dmat3 rotation = f / scale;
  for (int iteration = 0; iteration < 64; ++iteration) {
    const glm::dmat3 next = 0.5 * (rotation + glm::transpose(glm::inverse(rotation)));
    double change = 0;
    for (int c = 0; c < 3; ++c) change = std::max(change, glm::length(next[c] - rotation[c]));
    rotation = next;
    if (change < 1e-15) break;
  }
  return scale * rotation;
}

std::string deviation_text(double deviation) {
  std::ostringstream text;
  text << std::setprecision(2) << deviation;
  return text.str();
}

Importer::Importer(SourceManager& sources, const PbrtImportOptions& options, std::filesystem::path search_directory)
    : sources_(sources), options_(options), search_directory_(std::move(search_directory)) {
  auto matte = std::make_shared<MaterialInstance>();
  matte->type = "matte";  // pbrt-v3's default material: matte, Kd 0.5
  state_.material = matte;
  state_.named_materials = std::make_shared<std::map<std::string, std::shared_ptr<const MaterialInstance>>>();
  state_.spectrum_textures = std::make_shared<std::map<std::string, TextureEntry>>();
  state_.float_textures = std::make_shared<std::map<std::string, TextureEntry>>();
  // pbrt-v3's defaults when a scene leaves them out.
  result_.scene.settings.width = 1280;
  result_.scene.settings.height = 720;
  result_.scene.settings.spp = 16;
  result_.scene.settings.integrator = IntegratorType::path;
  result_.scene.settings.light_strategy = LightStrategy::spatial;
  result_.scene.settings.max_depth = 5;
}

void Importer::warn(SourceRange at, std::string message, std::string hint) {
  Diagnostic diagnostic = Diagnostic::warning(at, std::move(message));
  diagnostic.hint = std::move(hint);
  warnings_.push_back(std::move(diagnostic));
}

void Importer::report_unused(const ParamSet& params) {
  for (const Param* param : params.unused())
    warn(param->declaration,
         "parameter \"" + param->type_name + " " + param->name + "\" of " + params.context() + " is not used",
         "pbrt-v3 ignores it too (misspelt?)");
}

PbrtScene Importer::run(FileId main_file) {
  Parser parser(sources_, main_file, search_directory_, options_.read_file);
  SourceRange last{};
  while (std::optional<Directive> d = parser.next()) {
    last = d->range;
    if (block_ == Block::ended)
      fail(d->range, "directive after WorldEnd", "a scene file renders one image: one WorldBegin ... WorldEnd block");
    directive(*d);
  }
  if (block_ != Block::ended) {
    SourceLocation end = sources_.location_of(main_file, static_cast<uint32_t>(sources_.text(main_file).size()));
    SourceRange at = last.valid() ? last : SourceRange{end, end};
    fail(at, block_ == Block::options ? "the scene ends before WorldBegin" : "the scene ends before WorldEnd",
         "a truncated file? pbrt-v3 renders at WorldEnd");
  }
  if (motion_at_) set_shutter(*motion_at_);
  for (const Diagnostic& w : warnings_) result_.warnings += render_text(w, sources_);
  return std::move(result_);
}

void Importer::directive(const Directive& d) {
  for (const DirectiveRule& rule : kRules) {
    if (rule.name != d.name) continue;
    if (rule.where == Where::options && block_ != Block::options)
      fail(d.range, d.name + " must come before WorldBegin", "pbrt-v3 sets render options only outside the world block");
    if (d.name == "WorldBegin") return world_begin(d);
    if (rule.where == Where::options) return options_directive(d);
    return transform_directive(d);
  }
  if (block_ != Block::world)
    fail(d.range, d.name + " must come between WorldBegin and WorldEnd", "pbrt-v3 describes the scene in the world block");
  world_directive(d);
}

// ---------------------------------------------------------------------------
// Transforms (pbrt-v3: the current transform is post-multiplied)

void Importer::transform_directive(const Directive& d) {
  if (d.name == "CoordinateSystem") {
    coordinate_systems_[d.strings[0]] = {state_.transform.start, state_.transform.end};
  } else if (d.name == "CoordSysTransform") {
    auto found = coordinate_systems_.find(d.strings[0]);
    if (found == coordinate_systems_.end())
      fail(d.string_ranges[0], "no coordinate system named \"" + d.strings[0] + "\"",
           "CoordinateSystem names one; pbrt-v3 defines \"camera\" at Camera and \"world\" at WorldBegin");
    // As pbrt-v3: both times' transforms, whichever are active.
    state_.transform.start = found->second.first;
    state_.transform.end = found->second.second;
  } else if (d.name == "ActiveTransform") {
    state_.transform.start_active = d.strings[0] != "EndTime";
    state_.transform.end_active = d.strings[0] != "StartTime";
  } else if (d.name == "MediumInterface") {
    medium_interface(d);
  } else if (d.name == "MakeNamedMedium") {
    make_named_medium(d);
  } else {
    if (state_.transform.start_active) state_.transform.start = transformed(d, state_.transform.start);
    if (state_.transform.end_active) state_.transform.end = transformed(d, state_.transform.end);
  }
}

// With motion: the camera's shutter, which must be the span the two transforms
// are given at (pbrt-v3 interpolates between them, and so do we, but only
// between shutter open and close).
void Importer::set_shutter(SourceRange motion_at) {
  if (shutter_open_ != transform_start_time_ || shutter_close_ != transform_end_time_)
    fail(motion_at,
         "an animated transform with TransformTimes " + std::to_string(transform_start_time_) + " " +
             std::to_string(transform_end_time_) + " under a shutter open from " + std::to_string(shutter_open_) +
             " to " + std::to_string(shutter_close_) + " is not supported",
         "give the camera's \"float shutteropen\" and \"float shutterclose\" the TransformTimes");
  if (!(shutter_close_ > shutter_open_)) return;  // the shutter never opens: no blur, as in pbrt-v3
  Camera& camera = result_.scene.camera;
  camera.shutter_open = sg::from_raw<Time>(static_cast<Real>(shutter_open_));
  camera.shutter_close = sg::from_raw<Time>(static_cast<Real>(shutter_close_));
}

// `ctm` after one transform directive (pbrt-v3 post-multiplies).
Matrix Importer::transformed(const Directive& d, const Matrix& ctm) const {
  const std::vector<double>& n = d.numbers;
  Matrix next = ctm;
  if (d.name == "Identity") {
    next = Matrix(1.0);
  } else if (d.name == "Translate") {
    next = ctm * translate({n[0], n[1], n[2]});
  } else if (d.name == "Scale") {
    next = ctm * scale({n[0], n[1], n[2]});
  } else if (d.name == "Rotate") {
    if (!(glm::length(glm::dvec3(n[1], n[2], n[3])) > 0)) fail(d.arguments, "Rotate about a zero axis");
    next = ctm * rotate(n[0], {n[1], n[2], n[3]});
  } else if (d.name == "LookAt") {
    glm::dvec3 eye(n[0], n[1], n[2]), look(n[3], n[4], n[5]), up(n[6], n[7], n[8]);
    if (!(glm::length(look - eye) > 0)) fail(d.arguments, "LookAt: the eye and the point looked at coincide");
    if (!(glm::length(up) > 0)) fail(d.arguments, "LookAt: the up vector is zero");
    glm::dvec3 dir = glm::normalize(look - eye);
    glm::dvec3 side = glm::cross(glm::normalize(up), dir);
    if (!(glm::length(side) > 0))
      fail(d.arguments, "LookAt: the up vector is parallel to the viewing direction",
           "pbrt-v3 would fall back to the identity transform");
    glm::dvec3 right = glm::normalize(side), new_up = glm::cross(dir, right);
    Matrix world_from_camera(glm::dvec4(right, 0), glm::dvec4(new_up, 0), glm::dvec4(dir, 0), glm::dvec4(eye, 1));
    next = ctm * glm::inverse(world_from_camera);
  } else if (d.name == "Transform") {
    next = from_numbers(n);
  } else if (d.name == "ConcatTransform") {
    next = ctm * from_numbers(n);
  }
  if (!finite(next)) fail(span(d), d.name + " makes the transform non-finite");
  return next;
}

// ---------------------------------------------------------------------------
// Options block

void Importer::options_directive(const Directive& d) {
  if (d.name == "Camera") {
    if (d.strings[0] != "perspective" && d.strings[0] != "orthographic" && d.strings[0] != "environment")
      fail(d.string_ranges[0], "camera \"" + d.strings[0] + "\" is not supported",
           "supported: \"perspective\", \"orthographic\", \"environment\"");
    if (state_.transform.animated())
      fail(d.range, "an animated camera (a transform ActiveTransform changed at one time only) is not supported",
           "animate the objects instead: their motion blurs as pbrt-v3's does");
    camera_ = d;
    camera_from_world_ = state_.transform.start;
    const Matrix world_from_camera = invertible(state_.transform.start) ? glm::inverse(state_.transform.start) : Matrix(1.0);
    coordinate_systems_["camera"] = {world_from_camera, world_from_camera};
  } else if (d.name == "Film") {
    film(d);
  } else if (d.name == "Sampler") {
    sampler(d);
  } else if (d.name == "Integrator") {
    integrator(d);
  } else if (d.name == "PixelFilter") {
    pixel_filter(d);
  } else if (d.name == "Accelerator") {
    // Which acceleration structure pbrt-v3 builds changes its speed, not its image.
    ParamSet params(d.params, "Accelerator \"" + d.strings[0] + "\"");
    if (d.strings[0] != "bvh" && d.strings[0] != "kdtree")
      fail(d.string_ranges[0], "unknown accelerator \"" + d.strings[0] + "\"", "pbrt-v3 has \"bvh\" and \"kdtree\"");
  }
  if (d.name == "TransformTimes") {
    transform_start_time_ = d.numbers[0];
    transform_end_time_ = d.numbers[1];
    if (!(transform_end_time_ >= transform_start_time_))
      fail(d.arguments, "TransformTimes: the end time comes before the start time");
  }
}

void Importer::film(const Directive& d) {
  if (d.strings[0] != "image") fail(d.string_ranges[0], "film \"" + d.strings[0] + "\" is not supported", "supported: \"image\"");
  ParamSet params(d.params, "Film \"image\"");
  RenderSettings& settings = result_.scene.settings;
  settings.width = params.one_int("xresolution", 1280, 1, kMaxImageSide);
  settings.height = params.one_int("yresolution", 720, 1, kMaxImageSide);
  result_.film_filename = params.one_string("filename", "pbrt.exr");
  params.one_float("diagonal", 35);  // the realistic camera's sensor size
  // pbrt-v3's Film multiplies every pixel by it as it writes the image.
  settings.film_scale = params.one_float("scale", 1);
  if (!(settings.film_scale > 0) || !std::isfinite(settings.film_scale))
    params.fail_at(*params.find("scale", {ParamType::floating}), "Film \"float scale\" must be positive and finite");
  params.reject("maxsampleluminance", "samples are not clamped");
  result_.crop.reset();
  if (const Param* crop = params.find("cropwindow", {ParamType::floating})) {
    if (crop->numbers.size() != 4) fail(crop->values, "\"float cropwindow\" takes 4 values: x0 x1 y0 y1");
    // pbrt-v3's Film: the window in [0, 1]², rounded up to whole pixels.
    auto clamp01 = [](double v) { return std::min(1.0, std::max(0.0, v)); };
    double x0 = clamp01(std::min(crop->numbers[0], crop->numbers[1])), x1 = clamp01(std::max(crop->numbers[0], crop->numbers[1]));
    double y0 = clamp01(std::min(crop->numbers[2], crop->numbers[3])), y1 = clamp01(std::max(crop->numbers[2], crop->numbers[3]));
    CropWindow window;
    window.x = static_cast<int>(std::ceil(settings.width * x0));
    window.y = static_cast<int>(std::ceil(settings.height * y0));
    window.width = static_cast<int>(std::ceil(settings.width * x1)) - window.x;
    window.height = static_cast<int>(std::ceil(settings.height * y1)) - window.y;
    if (window.width < 1 || window.height < 1) fail(crop->values, "the crop window holds no pixel");
    if (window.x != 0 || window.y != 0 || window.width != settings.width || window.height != settings.height)
      result_.crop = window;
  }
  report_unused(params);
  film_ = d;
}

void Importer::sampler(const Directive& d) {
  const std::string& type = d.strings[0];
  ParamSet params(d.params, "Sampler \"" + type + "\"");
  // Which sequence pbrt-v3 draws changes only the noise: ours is always the
  // Owen-scrambled Sobol sampler. The sample count is pbrt's, rounded as it rounds.
  int spp = 0;
  auto round_up_to_power_of_2 = [](int n) {
    int p = 1;
    while (p < n) p *= 2;
    return p;
  };
  if (type == "halton" || type == "sobol" || type == "02sequence" || type == "lowdiscrepancy" || type == "maxmindist" ||
      type == "random") {
    spp = params.one_int("pixelsamples", type == "random" ? 4 : 16, 1, 1 << 24);
    if (type == "sobol" || type == "02sequence" || type == "lowdiscrepancy" || type == "maxmindist")
      spp = round_up_to_power_of_2(spp);
    if (type == "halton" && params.one_bool("samplepixelcenter", false))
      params.fail_at(*params.find("samplepixelcenter", {ParamType::boolean}),
                     "\"bool samplepixelcenter\" is not supported: our samples cover each pixel");
  } else if (type == "stratified") {
    int x = params.one_int("xsamples", 4, 1, 4096), y = params.one_int("ysamples", 4, 1, 4096);
    if (static_cast<long long>(x) * y > (1 << 24)) fail(d.range, "more than 2^24 samples per pixel");
    spp = x * y;
    params.one_bool("jitter", true);
  } else {
    fail(d.string_ranges[0], "unknown sampler \"" + type + "\"",
         "pbrt-v3 has \"halton\", \"sobol\", \"random\", \"stratified\", \"02sequence\" and \"maxmindist\"");
  }
  params.one_int("dimensions", 4, 0, 1 << 20);
  result_.scene.settings.spp = spp;
  report_unused(params);
}

void Importer::integrator(const Directive& d) {
  const std::string& type = d.strings[0];
  ParamSet params(d.params, "Integrator \"" + type + "\"");
  RenderSettings& settings = result_.scene.settings;
  integrator_name_ = type;
  integrator_at_ = d.string_ranges[0];
  integrator_traces_media_ = type == "volpath" || type == "bdpt" || type == "mlt";
  if (type == "path" || type == "volpath") {  // volpath: the path tracer, which traces media
    settings.integrator = IntegratorType::path;
    // Russian roulette: pbrt-v3's starts after 3 bounces below a throughput
    // threshold, ours after 3 bounces; both are unbiased. A threshold of 0 turns it off.
    settings.russian_roulette = params.one_float("rrthreshold", 1) > 0;
    settings.light_strategy = light_strategy(params, "lightsamplestrategy", "spatial", {"uniform", "power", "spatial"});
  } else if (type == "directlighting" || type == "whitted") {
    // Both are direct lighting plus perfectly specular chains up to maxdepth;
    // whitted samples every light once, directlighting (strategy "all")
    // every light its "nsamples" times, or (strategy "one") one light chosen uniformly.
    settings.integrator = IntegratorType::direct;
    settings.russian_roulette = false;  // neither plays it: their specular chains end at maxdepth
    settings.light_strategy = type == "whitted" ? LightStrategy::all : light_strategy(params, "strategy", "all", {"all", "one"});
    light_samples_per_light_ = type == "directlighting";
  } else if (type == "bdpt") {
    settings.integrator = IntegratorType::bdpt;
    // Ours chooses lights by power (as pbrt-v3's default for bdpt) and shows no strategies apart.
    for (std::string_view name : {"lightsamplestrategy", "visualizestrategies", "visualizeweights"})
      params.find(name, {ParamType::integer, ParamType::floating, ParamType::boolean, ParamType::string});
  } else if (type == "sppm") {
    settings.integrator = IntegratorType::sppm;
    read_sppm(params);
  } else if (const IntegratorSubstitute* substitute = substitute_for(type)) {
    settings.integrator = substitute->ours;
    for (std::string_view name : substitute->noise_only) {
      if (name.empty()) break;
      params.find(name, {ParamType::integer, ParamType::floating, ParamType::boolean, ParamType::string});
    }
    warn(d.string_ranges[0],
         "integrator \"" + type + "\" is not implemented: rendering with \"" + std::string(substitute->ours_name) + "\"",
         std::string(substitute->why));
  } else {
    fail(d.string_ranges[0], "integrator \"" + type + "\" is not supported",
         "supported: \"path\", \"volpath\", \"bdpt\", \"sppm\", \"directlighting\", \"whitted\" (as direct "
         "lighting); \"mlt\" (as bdpt)");
  }
  settings.max_depth = params.one_int("maxdepth", 5, 0, 1024);
  params.reject("pixelbounds", "render the whole image, or crop with --crop");
  report_unused(params);
}

// pbrt-v3's SPPM: "iterations" (or, in older versions, "numiterations"; 64)
// passes of "photonsperiteration" photons (the film's pixels when not
// positive), from visible points of initial "radius" (1, in scene units);
// "imagewritefrequency" (intermediate images) and pbrt-v4's "seed" change no pixel.
void Importer::read_sppm(ParamSet& params) {
  RenderSettings& settings = result_.scene.settings;
  settings.sppm_iterations = params.one_int("iterations", params.one_int("numiterations", 64, 1, 1 << 24), 1, 1 << 24);
  settings.sppm_photons_per_iteration = params.one_int("photonsperiteration", -1, -(1 << 30), 1 << 28);
  const double radius = params.one_float("radius", 1);
  settings.sppm_radius = radius > 0 && std::isfinite(radius)
                             ? sg::from_raw<Length>(static_cast<Real>(radius * options_.metres_per_unit))
                             : Length(sg::zero);
  for (std::string_view name : {"imagewritefrequency", "seed"})
    params.find(name, {ParamType::integer, ParamType::floating, ParamType::boolean, ParamType::string});
}

// A light-choice parameter of pbrt-v3's integrators as our strategy ("one":
// uniform). An unknown name is pbrt-v3's error message and its default.
LightStrategy Importer::light_strategy(ParamSet& params, std::string_view name, std::string_view fallback,
                                       std::initializer_list<std::string_view> known) {
  std::string value = params.one_string(name, std::string(fallback));
  if (std::find(known.begin(), known.end(), value) == known.end()) {
    std::string list;
    for (std::string_view k : known) list += (list.empty() ? "\"" : ", \"") + std::string(k) + "\"";
    warn(params.find(name, {ParamType::string})->values,
         "unknown \"string " + std::string(name) + "\" \"" + value + "\": using \"" +
             std::string(fallback) + "\", as pbrt-v3 does",
         "pbrt-v3 has " + list);
    value = fallback;
  }
  return value == "one" ? LightStrategy::uniform : *light_strategy_named(value);
}

// pbrt-v3's filters, with its defaults; a "width" is the filter's radius in pixels.
void Importer::pixel_filter(const Directive& d) {
  const std::string& type = d.strings[0];
  ParamSet params(d.params, "PixelFilter \"" + type + "\"");
  const std::optional<PixelFilterType> named = pixel_filter_named(type);
  if (!named)
    fail(d.string_ranges[0], "unknown pixel filter \"" + type + "\"",
         "expected " + quoted_choices(kPixelFilterNames) + " (pbrt-v3's five)");
  PixelFilter filter;
  filter.type = *named;
  // Each number bounded (the JSON loader bounds its own alike): a filter of NaNs would make NaN pixels.
  auto read = [&](const char* name, double fallback, double low, double high, const char* what) {
    const double value = params.one_float(name, fallback);
    if (!(value > low && value <= high))
      params.fail_at(*params.find(name, {ParamType::floating}),
                     std::string("a filter's \"float ") + name + "\" must be " + what);
    return value;
  };
  // The radii as the JSON loader bounds them.
  auto radius = [&](const char* name) {
    const double value = params.one_float(name, default_filter_radius(filter.type));
    if (!(value >= kMinFilterRadius && value <= kMaxFilterRadius))
      params.fail_at(*params.find(name, {ParamType::floating}),
                     std::string("a filter's \"float ") + name + "\" must be 0.001 to 64 pixels");
    return value;
  };
  filter.radius_x = radius("xwidth");
  filter.radius_y = radius("ywidth");
  if (filter.type == PixelFilterType::gaussian) filter.gaussian_alpha = read("alpha", 2, 0, 1e6, "in (0, 1e6]");
  if (filter.type == PixelFilterType::mitchell) {
    filter.mitchell_b = read("B", 1.0 / 3, -10, 10, "in (-10, 10]");
    filter.mitchell_c = read("C", 1.0 / 3, -10, 10, "in (-10, 10]");
  }
  if (filter.type == PixelFilterType::sinc) filter.sinc_tau = read("tau", 3, 0, 1e3, "in (0, 1000]");
  report_unused(params);
  filter.mode = PixelFilterMode::splat;  // pbrt-v3's Film::AddSample
  result_.scene.settings.filter = filter;
}

// ---------------------------------------------------------------------------
// WorldBegin: the camera and the mapping to our world

void Importer::world_begin(const Directive& d) {
  finish_camera(d.range);
  block_ = Block::world;
  state_.transform.start = state_.transform.end = Matrix(1.0);
  coordinate_systems_["world"] = {state_.transform.start, state_.transform.end};
}

// Without a Camera directive pbrt-v3 looks down +z from the origin, fov 90.
// pbrt-v3's default screen window spans [-1, 1] across the film's shorter axis. A
// window that scales it by s is a wider or narrower view, which our cameras express
// directly; a shifted or stretched one is not.
double Importer::screen_window_scale(ParamSet& params, SourceRange at) {
  const RenderSettings& settings = result_.scene.settings;
  double aspect = static_cast<double>(settings.width) / settings.height;
  double frame_aspect = params.one_float("frameaspectratio", aspect);
  if (std::fabs(frame_aspect - aspect) > 1e-6 * aspect)
    fail(at, "a \"frameaspectratio\" other than the film's is not supported", "our pixels are square");
  const Param* window = params.find("screenwindow", {ParamType::floating});
  if (!window) return 1;
  double fx = aspect > 1 ? aspect : 1, fy = aspect > 1 ? 1 : 1 / aspect;
  const std::vector<double>& w = window->numbers;
  double s = w.size() == 4 ? w[1] / fx : 0;
  if (!(s > 0 && std::isfinite(s)) || std::fabs(w[0] + s * fx) > 1e-6 * s * fx ||
      std::fabs(w[2] + s * fy) > 1e-6 * s * fy || std::fabs(w[3] - s * fy) > 1e-6 * s * fy) {
    std::ostringstream expected;
    expected << "expected [-" << fx << "s " << fx << "s -" << fy << "s " << fy << "s] for some s > 0";
    fail(window->declaration, "only a \"screenwindow\" centred on the view with the film's aspect is supported",
         expected.str());
  }
  return s;
}

// The camera frame (the linear part of camera → pbrt world) as a uniformly
// scaled rotation or mirroring, the only frames our cameras have. Exporters
// write transforms rounded to a few significant digits (Houdini: 4, a rotation
// off by ~1e-4), which pbrt-v3 renders as written, sheared by as little: such a
// frame is replaced by the nearest similarity, with a warning saying how far off
// it was. One further off than rounding explains scales unevenly or shears on
// purpose, which pbrt-v3 renders and we cannot: an error.
glm::dmat3 Importer::similarity_camera_frame(const glm::dmat3& frame, SourceRange at) {
  const double deviation = deviation_from_similarity(frame);
  if (deviation > kRoundedSimilarity)
    fail(at, "the camera transform scales unevenly or shears (off a rotation by " + deviation_text(deviation) + ")",
         "only rotations, mirrorings and uniform scales place a camera here; numbers rounded to 3 or more "
         "significant digits are accepted");
  warn_if_rounded(at, "the camera transform", deviation);
  return nearest_similarity(frame);
}

// A transform that should be a scaled rotation, off by `deviation`
// (deviation_from_similarity) within what rounded numbers leave: said when
// it is more than double arithmetic leaves.
void Importer::warn_if_rounded(SourceRange at, const std::string& subject, double deviation) {
  if (deviation <= kExactSimilarity) return;
  warn(at, subject + " is a rotation only to within " + deviation_text(deviation) + ": rendered with the nearest rotation",
       "numbers rounded by an exporter? pbrt-v3 renders the transform as written, sheared by as much");
}

void Importer::finish_camera(SourceRange world_begin) {
  Camera& camera = result_.scene.camera;
  SourceRange at = camera_ ? camera_->range : world_begin;
  if (!invertible(camera_from_world_)) fail(at, "the camera transform is singular");
  Matrix pbrt_world_from_camera = glm::inverse(camera_from_world_);
  glm::dmat3 frame = similarity_camera_frame(glm::dmat3(pbrt_world_from_camera), at);
  for (int c = 0; c < 3; ++c) pbrt_world_from_camera[c] = glm::dvec4(frame[c], 0);
  const double sx = glm::length(frame[0]);
  // Our image's right is forward × up: a right-handed camera frame (pbrt's
  // LookAt) needs the world mirrored for the image to come out as pbrt's.
  bool mirror = glm::determinant(frame) > 0;
  double unit = options_.metres_per_unit;
  world_from_pbrt_world_ = scale({mirror ? -unit : unit, unit, unit});
  Matrix world_from_camera = world_from_pbrt_world_ * pbrt_world_from_camera;
  camera.position = to_world_point(world_from_camera, {0, 0, 0}, at);
  glm::dvec3 forward = glm::normalize(glm::dvec3(world_from_camera[2]));
  glm::dvec3 up = glm::normalize(glm::dvec3(world_from_camera[1]));
  camera.look_at = to_world_point(Matrix(1.0), glm::dvec3(world_from_camera[3]) + forward, at);
  camera.up = sg::normalize(sg::from_raw<vector<World, dim::dimensionless>>(sg::vec3_rep(up)));

  static const std::vector<Param> kNoParams;
  const std::string type = camera_ ? camera_->strings[0] : "perspective";
  ParamSet params(camera_ ? camera_->params : kNoParams, "Camera \"" + type + "\"");
  double metres_per_camera_unit = sx * unit;
  const double window_scale = type == "environment" ? 1 : screen_window_scale(params, at);
  if (type == "perspective") {
    double fov = params.one_float("fov", 90);
    double half_fov = params.one_float("halffov", -1);
    if (half_fov > 0) fov = 2 * half_fov;
    if (!(fov > 0 && fov < 180)) fail(at, "the field of view must lie in (0, 180) degrees");
    // A scaled window widens the view as a wider field of view would: tan(fov'/2) = s tan(fov/2).
    fov = 2 * std::atan(window_scale * std::tan(fov * std::numbers::pi / 360)) * 180 / std::numbers::pi;
    camera.fov = static_cast<Real>(fov) * units::degree;
  } else if (type == "orthographic") {
    camera.projection = CameraProjection::orthographic;
    camera.view_size = sg::from_raw<Length>(static_cast<Real>(2 * window_scale * metres_per_camera_unit));
    if (!(camera.view_size > sg::zero) || !std::isfinite(sg::raw(camera.view_size)))
      fail(at, std::string("the orthographic view is out of ") + kRealName + " range at this --length-unit");
  } else {
    // pbrt-v3's environment camera sees every direction: it reads no lens, window or aspect.
    camera.projection = CameraProjection::environment;
  }
  double lens_radius = type == "environment" ? 0 : params.one_float("lensradius", 0);
  if (lens_radius < 0) fail(at, "\"float lensradius\" must not be negative");
  camera.lens_radius = sg::from_raw<Length>(static_cast<Real>(lens_radius * metres_per_camera_unit));
  double focal_distance = type == "environment" ? 1e6 : params.one_float("focaldistance", 1e6);
  if (!(focal_distance > 0)) fail(at, "\"float focaldistance\" must be positive");
  camera.focus_distance = sg::from_raw<Length>(static_cast<Real>(focal_distance * metres_per_camera_unit));
  if (!std::isfinite(sg::raw(camera.focus_distance)) || !std::isfinite(sg::raw(camera.lens_radius)))
    fail(at, std::string("the lens is out of ") + kRealName + " range at this --length-unit");
  // Used once a shape moves (ActiveTransform): pbrt-v3's times, as seconds.
  shutter_open_ = params.one_float("shutteropen", 0);
  shutter_close_ = params.one_float("shutterclose", 1);
  report_unused(params);
}

PointWorld Importer::to_world_point(const Matrix& m, glm::dvec3 p, SourceRange at) const {
  glm::dvec4 q = m * glm::dvec4(p, 1.0);
  sg::vec3_rep f(q);
  if (!std::isfinite(f.x) || !std::isfinite(f.y) || !std::isfinite(f.z))
    fail(at, std::string("a coordinate is out of ") + kRealName + " range at --length-unit of " +
                 std::to_string(options_.metres_per_unit) + " m");
  return sg::from_raw<PointWorld>(f);
}

}  // namespace pbrt

// ---------------------------------------------------------------------------
// Entry points

namespace {

std::filesystem::path directory_of(const std::filesystem::path& file) {
  std::filesystem::path parent = file.parent_path();
  return parent.empty() ? std::filesystem::path(".") : parent;
}

}  // namespace

PbrtScene parse_pbrt_scene(std::string text, const std::string& display_name,
                           const std::filesystem::path& search_directory, const PbrtImportOptions& options) {
  if (!(options.metres_per_unit > 0) || !std::isfinite(options.metres_per_unit))
    throw PbrtImportError(display_name + ": pbrt scenes carry no units: say what one pbrt length unit is "
                          "(safegi-render --length-unit m|cm|mm|...)\n");
  PbrtImportOptions resolved = options;
  if (!resolved.read_file) resolved.read_file = pbrt::disk_reader();
  SourceManager sources;
  FileId main_file = sources.add_file(display_name, std::move(text));
  try {
    return pbrt::Importer(sources, resolved, search_directory).run(main_file);
  } catch (const pbrt::PbrtError& error) {
    throw PbrtImportError(render_text(error.diagnostic(), sources));
  }
}

PbrtScene load_pbrt_scene(const std::filesystem::path& file, const PbrtImportOptions& options) {
  PbrtFileReader read = options.read_file ? options.read_file : pbrt::disk_reader();
  std::string error;
  std::optional<std::string> text = read(file, error);
  if (!text) throw PbrtImportError(file.string() + ": cannot open scene file: " + error + "\n");
  return parse_pbrt_scene(std::move(*text), file.string(), directory_of(file), options);
}

double parse_length_unit(const std::string& text) {
  const std::string expected = "--length-unit: expected a length unit (m, cm, mm, in, ...), got '" + text + "'";
  std::string unit_error, quantity_error;
  std::optional<Quantity> length;
  if (std::optional<Unit> unit = parse_unit(text, unit_error)) length = Quantity{unit->to_reference, unit->dimension};
  else if (std::optional<Quantity> quantity = parse_quantity(text, quantity_error)) length = quantity;  // "0.5 m"
  if (!length) throw SceneError(expected + ": " + unit_error);
  if (!(length->dimension == runtime_dim::length)) throw SceneError(expected + " (" + dimension_name(length->dimension) + ")");
  if (!(length->value > 0) || !std::isfinite(length->value))
    throw SceneError("--length-unit: one pbrt unit must be a positive length, got '" + text + "'");
  return length->value;
}

}  // namespace safegi::render
