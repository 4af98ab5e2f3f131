// pbrt-v3 scene files, stage 3: directives → Scene. The graphics state
// (transform, material, area light, named materials and textures, attribute
// stack) follows pbrt-v3's core/api.cpp; what the renderer cannot represent is
// an error at the directive or parameter that asks for it.
//
// Coordinates: pbrt-v3's camera space has x to the image's right, y up and z
// forward, a left-handed frame when the camera transform is a rotation (as
// LookAt makes it). Our camera's right is forward × up, so when the camera
// frame is right-handed the whole scene is mirrored across x (camera
// included): the image is pbrt's, the world coordinates are mirrored. Every
// length is then scaled by the metres in one pbrt unit.
#pragma once

#include <glm/glm.hpp>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "pbrt/pbrt_params.hpp"
#include "safegi/cpu_renderer/pbrt_import.hpp"

namespace safegi::render::pbrt {

using Matrix = glm::dmat4;  // column-major, as glm: m[column][row]

struct MaterialInstance {
  std::string type;              // "matte", "mirror", ...
  std::vector<Param> params;
  SourceRange at;                // the directive's type name
  mutable int index = -2;        // its Scene material without overrides; -2: not made yet
  bool invisible = false;        // "" or "none": no surface, only a boundary of media
  // What is wrong with it, reported only when a shape uses it: pbrt-v3 makes a
  // material for its shapes, so one that is overridden before any shape is harmless.
  std::optional<Diagnostic> error;
};

// A texture as the Scene can hold it: a value times, optionally, an image or
// a pattern (pbrt's "constant", "imagemap", procedural textures, and "scale"
// or "mix" of a constant and one of those; of two patterns, a pattern).
struct TextureEntry {
  std::string texture_class;  // "constant", "imagemap", "checkerboard", "scale", ...
  Rgb value{1, 1, 1};         // a constant's value, or the factor on `image` or `pattern`
  int image = -1;             // index into Scene::textures; -1: none
  int pattern = -1;           // index into Scene::patterns; -1: none
  bool textured() const { return image >= 0 || pattern >= 0; }
  SourceRange at;
  std::optional<Diagnostic> error;  // as MaterialInstance::error: reported when a used material reads it
};

struct AreaLight {
  Rgb radiance{};
  bool two_sided = false;
  int samples = 1;  // shadow rays per shading point under pbrt-v3's directlighting
  SourceRange at;
};

template <class T>
using SharedMap = std::shared_ptr<std::map<std::string, T>>;

// pbrt-v3's current transform, object → pbrt world (in the options block: world →
// camera): one at each of its two TransformTimes, and which of them the transform
// directives change (ActiveTransform). They differ only where ActiveTransform made
// them: a shape placed under them moves.
struct TransformSet {
  Matrix start{1.0};  // at the first of the TransformTimes
  Matrix end{1.0};    // at the second
  bool start_active = true, end_active = true;
  bool animated() const { return start != end; }
};

// A medium as MediumInterface names it ("": vacuum), and where.
struct NamedMedium {
  std::string name;
  SourceRange at;
};

struct GraphicsState {
  TransformSet transform;
  bool reverse_orientation = false;
  std::shared_ptr<const MaterialInstance> material;
  std::optional<AreaLight> area_light;
  SharedMap<std::shared_ptr<const MaterialInstance>> named_materials;
  SharedMap<TextureEntry> spectrum_textures, float_textures;
  NamedMedium inside_medium, outside_medium;  // MediumInterface's
};

// A shape as pbrt-v3 made it: object-space data, its transform and
// orientation; placed into the Scene once the world mapping is known (at
// once, or at each ObjectInstance of its object).
struct ShapeSource {
  enum class Kind { mesh, sphere } kind = Kind::mesh;
  std::vector<glm::dvec3> positions;  // object space, pbrt units
  std::vector<glm::dvec3> normals;    // "N": shading normals, and the side emitters emit on
  std::vector<uint32_t> indices;
  std::vector<TexCoord> uvs;         // "uv"/"st": empty or one per position
  double radius = 0;                 // sphere
  Matrix pbrt_world_from_object{1.0};
  std::optional<Matrix> pbrt_world_from_object_at_end;  // an animated transform (motion blur)
  bool reverse_orientation = false;
  int material = -1;
  bool invisible = false;                 // material "" or "none": no surface
  std::optional<TexturedReflectance> alpha, shadow_alpha;  // pbrt-v3's masks
  std::optional<MediumInterface> media;  // where the two sides' differ
  std::optional<AreaLight> emission;
  int pbrt_lights = 1;  // the lights pbrt-v3 makes of it as an emitter: one per triangle of a mesh
  SourceRange at;
};

// pbrt-v3's quadrics as triangle meshes in object space (pbrt_quadrics.cpp):
// "disk", "cylinder", "cone", "paraboloid", "hyperboloid" (false for any other
// type), and a sphere cut by zmin, zmax or phimax (false for a whole one,
// unless `even_if_whole`: the mesh of an ellipsoid, a sphere scaled unevenly).
bool quadric_mesh(const std::string& type, ParamSet& params, SourceRange at, ShapeSource& source);
bool sphere_mesh(double radius, bool even_if_whole, ParamSet& params, SourceRange at, ShapeSource& source);
// Two triangles per cell of a grid of `columns` × `rows` vertices already in
// source.positions (u fastest), wound about ∂p/∂u × ∂p/∂v; cells' triangles of no
// area (an apex, a disk's centre) left out.
void triangulate_grid(int columns, int rows, ShapeSource& source);
// pbrt-v3's "nurbs" as the mesh pbrt-v3 dices it into (pbrt_nurbs.cpp); false for any other type.
bool nurbs_mesh(const std::string& type, ParamSet& params, SourceRange at, ShapeSource& source);
// pbrt-v3's "heightfield" as the mesh pbrt-v3 makes of it (pbrt_heightfield.cpp); false for any other type.
bool heightfield_mesh(const std::string& type, ParamSet& params, SourceRange at, ShapeSource& source);
// pbrt-v3's "loopsubdiv" as the mesh its LoopSubdivide makes (pbrt_loopsubdiv.cpp),
// its limit normals as "N"; false for any other type.
bool loopsubdiv_mesh(const std::string& type, ParamSet& params, SourceRange at, ShapeSource& source);
// pbrt-v3's "curve" as a tube ("cylinder", "flat") or a strip ("ribbon") of
// triangles along its Bézier segments (pbrt_curves.cpp); false for any other
// type. `curve_triangles`: what the scene's curves made before this one,
// refused before it tessellates once they pass what fits in memory (a hair
// file of a million segments would make hundreds of millions).
bool curve_mesh(const std::string& type, ParamSet& params, SourceRange at, ShapeSource& source,
                uint64_t& curve_triangles);
struct SubdivisionSurface {
  std::vector<glm::dvec3> positions;  // on the limit surface
  std::vector<glm::dvec3> normals;    // pbrt-v3's limit normals, not normalised
  std::vector<uint32_t> indices;
};
// pbrt-v3's LoopSubdivide of a control mesh whose indices are in range and
// whose every vertex is in some triangle; a topology pbrt-v3 cannot subdivide
// is an error at `at`.
SubdivisionSurface loop_subdivide(std::vector<glm::dvec3> control_points, const std::vector<uint32_t>& indices, int levels,
                                  SourceRange at);
// What subdividing, importing and rendering a triangle of it takes, about: a
// "loopsubdiv" whose levels make more triangles than fit in the memory a
// render may take (memory_estimate.hpp) is refused.
uint64_t loop_subdivision_bytes_per_triangle();

// How far a linear map is from a uniformly scaled rotation or mirroring: the
// largest entry of FᵀF/s² − I, s² the mean squared column length.
double deviation_from_similarity(const glm::dmat3& f);
// The uniformly scaled rotation (or mirroring) nearest an invertible map.
glm::dmat3 nearest_similarity(const glm::dmat3& f);
std::string deviation_text(double deviation);  // as messages quote it: 2 significant digits
// What double arithmetic on exact rotations leaves, and what numbers rounded
// to 3 significant digits leave (up to ~2e-3; 4 digits, ~2e-4): a transform
// that should be a scaled rotation is taken as the nearest one up to the
// second, with a warning beyond the first (Importer::warn_if_rounded).
inline constexpr double kExactSimilarity = 1e-5;
inline constexpr double kRoundedSimilarity = 1e-2;

class Importer {
 public:
  Importer(SourceManager& sources, const PbrtImportOptions& options, std::filesystem::path search_directory);
  PbrtScene run(FileId main_file);

 private:
  enum class Block { options, world, ended };

  void directive(const Directive& d);
  void transform_directive(const Directive& d);
  Matrix transformed(const Directive& d, const Matrix& ctm) const;
  void set_shutter(SourceRange motion_at);
  void options_directive(const Directive& d);
  void world_begin(const Directive& d);
  void world_directive(const Directive& d);

  // Options block (pbrt_importer.cpp).
  void film(const Directive& d);
  void sampler(const Directive& d);
  void integrator(const Directive& d);
  LightStrategy light_strategy(ParamSet& params, std::string_view name, std::string_view fallback,
                               std::initializer_list<std::string_view> known);
  void pixel_filter(const Directive& d);
  void read_sppm(ParamSet& params);
  void fall_back_from_bdpt(SourceRange world_end);
  void finish_camera(SourceRange world_begin);
  glm::dmat3 similarity_camera_frame(const glm::dmat3& frame, SourceRange at);
  void warn_if_rounded(SourceRange at, const std::string& subject, double deviation);
  glm::dmat3 light_rotation(const Matrix& m, SourceRange at, const std::string& type);
  double screen_window_scale(ParamSet& params, SourceRange at);

  // Materials and textures (pbrt_materials.cpp).
  void material(const Directive& d, bool named);
  void make_material(MaterialInstance& instance, ParamSet& params);
  int material_index(const MaterialInstance& material, ParamSet& shape_params);
  Material convert_material(const std::string& type, ParamSet& params, SourceRange at);
  Material convert_uber(ParamSet& params, SourceRange at);
  Material convert_mix(ParamSet& params, SourceRange at);
  Material mixed_with_pass_through(Material opaque, const TexturedReflectance& opacity);
  TextureEntry combined_texture(const std::string& name, const std::string& texture_class, ParamSet& params,
                                bool spectrum);
  int mixed_material(ParamSet& params, const char* name, SourceRange at);
  MaterialModel plastic(const TexturedReflectance& kd, Reflectance ks, double alpha, double ior, bool pbrt_v3_fresnel,
                        const ParamSet& params, SourceRange at);
  static MaterialModel glass(Reflectance kr, Reflectance kt, double ior);
  MaterialModel glass(ParamSet& params, SourceRange at);
  MaterialModel metal(ParamSet& params, SourceRange at);
  MaterialModel substrate(ParamSet& params, SourceRange at);
  MaterialModel translucent(ParamSet& params, SourceRange at);
  MaterialModel disney(ParamSet& params, SourceRange at);  // pbrt_disney.cpp
  Real disney_float(ParamSet& params, const char* name, double fallback, double low, double high);
  IndexSpectrum index_spectrum(ParamSet& params, const char* name, const Rgb& fallback, bool zero_allowed);
  static double isotropic_roughness(double u, double v, const ParamSet& params, SourceRange at,
                                    bool reads_roughness = true);
  static Real checked_alpha(double alpha, const ParamSet& params, SourceRange at);
  std::optional<TextureEntry> spectrum_or_texture(ParamSet& params, const char* name, const Param*& param);
  std::optional<double> float_param(ParamSet& params, const char* name);
  std::optional<TextureEntry> float_or_texture(ParamSet& params, const char* name, const Param*& param);
  std::optional<BumpMap> bump_map(ParamSet& params);
  Reflectance reflectance(ParamSet& params, const char* name, double fallback);
  // How a spectrum parameter reads a texture: not at all, as a reflectance
  // (above 1 rendered as pbrt-v3 renders it, warned), or as a mix's weight
  // (clamped to [0, 1]).
  enum class TextureUse { none, reflectance, weight };
  TexturedReflectance textured_reflectance(ParamSet& params, const char* name, double fallback, TextureUse use);
  Reflectance texture_maximum(int image, int pattern);
  bool warned_above_one(const TexturedReflectance& kd) const;  // its texture alone exceeds 1, said once
  double roughness_alpha(ParamSet& params, const char* name, double fallback, bool remap);
  double index_of_refraction(ParamSet& params, SourceRange at);
  void texture(const Directive& d);
  TextureEntry convert_texture(const Directive& d, bool spectrum);
  int image_texture(const std::string& name, ParamSet& params, SourceRange at);
  // Mappings and procedural textures (pbrt_patterns.cpp).
  Mapping2D mapping_2d(ParamSet& params, SourceRange at);
  SolidMapping solid_mapping(SourceRange at, bool in_texture_space = true);
  Reflectance pattern_colour(ParamSet& params, const char* name, double fallback, bool spectrum);
  std::optional<Pattern> pattern(const std::string& texture_class, ParamSet& params, SourceRange at, bool spectrum);
  Image read_image(const Param& filename);

  // Participating media (pbrt_media.cpp).
  void make_named_medium(const Directive& d);
  spectrum<dim::inv_length> coefficients(ParamSet& params, const char* name, const Rgb& fallback, double scale,
                                         const Param* scale_param);
  void medium_interface(const Directive& d);
  int medium_index(const NamedMedium& medium);
  std::optional<MediumInterface> shape_media();
  void finish_media(SourceRange world_end);

  // World block (pbrt_world.cpp).
  void light_source(const Directive& d);
  void infinite_light(const Directive& d, ParamSet& params);
  PointLight mapped_point_light(const Directive& d, ParamSet& params, Intensity intensity);
  void distant_light(const Directive& d, ParamSet& params);
  void area_light_source(const Directive& d);
  void shape(const Directive& d);
  std::optional<TexturedReflectance> alpha_mask(ParamSet& params, const char* name);
  void mesh_from_ply(const Directive& d, ParamSet& params, ShapeSource& source);
  void place(const ShapeSource& source, const Matrix& world_from_pbrt_world);
  void animate(const ShapeSource& source, const Matrix& world_from_pbrt_world, Shape& shape);
  void object_instance(const Directive& d);

  void warn(SourceRange at, std::string message, std::string hint = {});
  void report_unused(const ParamSet& params);
  PointWorld to_world_point(const Matrix& m, glm::dvec3 p, SourceRange at) const;

  SourceManager& sources_;
  PbrtImportOptions options_;
  std::filesystem::path search_directory_;
  Block block_ = Block::options;
  PbrtScene result_;
  std::vector<Diagnostic> warnings_;
  std::set<std::string> formats_beyond_pbrt_warned_;  // image formats pbrt-v3 does not read, warned once each
  std::set<std::pair<int, int>> textures_above_one_warned_;  // (image, pattern) reaching above 1, warned once each
  std::map<std::pair<int, int>, Reflectance> texture_maxima_;  // texture_maximum's, by (image, pattern)
  uint64_t curve_triangles_ = 0;                       // made of the curves so far
  std::optional<SourceRange> environment_at_;  // the infinite light, once there is one
  std::map<std::string, int> named_media_;     // into Scene::media
  bool media_used_ = false;                    // by a shape or the camera
  std::string integrator_name_ = "path";       // pbrt-v3's default
  std::optional<SourceRange> integrator_at_;
  bool integrator_traces_media_ = false;       // volpath, bdpt, mlt
  bool light_samples_per_light_ = false;      // directlighting: area lights' "nsamples" count

  GraphicsState state_;
  std::vector<GraphicsState> attribute_stack_;
  std::vector<TransformSet> transform_stack_;
  std::map<std::string, std::pair<Matrix, Matrix>> coordinate_systems_;  // at the start and the end time
  double transform_start_time_ = 0, transform_end_time_ = 1;           // TransformTimes
  std::optional<SourceRange> motion_at_;                                // the first animated shape
  double shutter_open_ = 0, shutter_close_ = 1;                         // the camera's

  // Options kept until WorldBegin, where the camera can be placed.
  std::optional<Directive> camera_;
  Matrix camera_from_world_{1.0};
  std::optional<Directive> film_;
  Matrix world_from_pbrt_world_{1.0};  // mirror (if needed) and length unit

  // Object instancing: definitions are flattened into copies.
  std::map<std::string, std::vector<ShapeSource>> objects_;
  std::vector<ShapeSource>* current_object_ = nullptr;
  std::string current_object_name_;
};

}  // namespace safegi::render::pbrt
