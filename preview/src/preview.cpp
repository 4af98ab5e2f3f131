#include "safegi/preview/preview.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <variant>

#include <glm/gtc/matrix_transform.hpp>
#include <safegi/runtime_gl/gl.hpp>
#include <safegi/runtime_gl/runtime_gl.hpp>

#include "program_loader.hpp"
#include "scene_meshes.hpp"

namespace safegi::preview {

namespace {

// The clip space of one cube face of a light (shade.sgl.frag, shadow_depth.sgl.vert).
struct LightClip : space_tag<"light_clip"> {};

using Clip = spaces::clip;
using ClipFromWorld = projective_map<World, Clip>;
using LightClipFromWorld = projective_map<World, LightClip>;
using Area = quantity<dim::area>;
using Defines = std::vector<std::pair<std::string, std::string>>;

constexpr float kFarDistance = 1e30f;  // what an empty shadow-map texel holds, in metres

// The uniforms every camera pass shares (scene.sgl.vert, shade.sgl.frag).
struct CameraHandles {
  gl::uniform_id<RenderFromObject> world_from_object;
  gl::uniform_id<ClipFromWorld> clip_from_world;
  gl::uniform_id<PointWorld> eye;
  gl::uniform_id<NormalWorld> clip_normal;
  gl::uniform_id<PointWorld> clip_point;
  explicit CameraHandles(const gl::Program& p)
      : world_from_object(p.uniform<RenderFromObject>("worldFromObject")),
        clip_from_world(p.uniform<ClipFromWorld>("clipFromWorld")),
        eye(p.uniform<PointWorld>("eye")),
        clip_normal(p.uniform<NormalWorld>("clipNormal")),
        clip_point(p.uniform<PointWorld>("clipPoint")) {}
};

struct EmissionPass {
  gl::Program program;
  CameraHandles camera{program};
  gl::uniform_id<Radiance> le = program.uniform<Radiance>("Le");
  gl::uniform_id<int32_t> two_sided = program.uniform<int32_t>("emitterTwoSided");
  gl::output_id<Radiance> radiance = program.output<Radiance>("radiance");
};

// A light pass (POINT_LIGHT or AREA_SAMPLE): material, light position, shadow map.
struct LightPass {
  gl::Program program;
  CameraHandles camera{program};
  gl::uniform_id<Reflectance> kd = program.uniform<Reflectance>("Kd");
  gl::uniform_id<Reflectance> ks = program.uniform<Reflectance>("Ks");
  gl::uniform_id<float> exponent = program.uniform<float>("phongExponent");
  gl::uniform_id<PointWorld> light_position = program.uniform<PointWorld>("lightPosition");
  gl::sampler_id<Length> shadow_map = program.sampler<Length>("shadowMap");
  gl::uniform_array_id<LightClipFromWorld> shadow_clip_from_world =
      program.uniform_array<LightClipFromWorld>("shadowClipFromWorld");
  gl::uniform_id<float> face_texels = program.uniform<float>("shadowFaceTexels");
  gl::uniform_id<float> bias_texels = program.uniform<float>("shadowBiasTexels");
  gl::output_id<Radiance> radiance = program.output<Radiance>("radiance");
};

// Point and spot lights (a point light is a spot whose cone is everything).
struct PointLightPass : LightPass {
  gl::uniform_id<Intensity> intensity = program.uniform<Intensity>("lightIntensity");
  gl::uniform_id<DirectionWorld> spot_axis = program.uniform<DirectionWorld>("spotAxis");
  gl::uniform_id<float> spot_cos_total = program.uniform<float>("spotCosTotal");
  gl::uniform_id<float> spot_cos_start = program.uniform<float>("spotCosStart");
};

// A planar mirror's surface: Kr times what its reflection pass saw at each pixel.
struct MirrorPass {
  gl::Program program;
  CameraHandles camera{program};
  gl::uniform_id<Reflectance> kr = program.uniform<Reflectance>("Kr");
  gl::sampler_id<Radiance> reflection = program.sampler<Radiance>("reflection");
};

struct AreaSamplePass : LightPass {
  gl::uniform_id<Radiance> le = program.uniform<Radiance>("Le");
  gl::uniform_id<Area> sample_area = program.uniform<Area>("sampleArea");
  gl::uniform_id<NormalWorld> emitter_normal = program.uniform<NormalWorld>("emitterNormal");
  gl::uniform_id<int32_t> two_sided = program.uniform<int32_t>("emitterTwoSided");
};

struct DepthPass {
  gl::Program program;
  gl::uniform_id<RenderFromObject> world_from_object = program.uniform<RenderFromObject>("worldFromObject");
  gl::uniform_id<LightClipFromWorld> light_clip_from_world =
      program.uniform<LightClipFromWorld>("lightClipFromWorld");
  gl::uniform_id<PointWorld> light_position = program.uniform<PointWorld>("lightPosition");
  gl::output_id<Length> distance = program.output<Length>("lightDistance");
};

ShaderFormat format_of(const PreviewOptions& options) {
  return options.spirv_shaders ? ShaderFormat::spirv : ShaderFormat::glsl;
}

gl::Program camera_program(const char* define, const char* name, const PreviewOptions& options) {
  return load_embedded_program({"scene.sgl.vert", "shade.sgl.frag"}, Defines{{define, "1"}}, name, format_of(options));
}

// Where a pass looks from: the camera, or the camera seen through a mirror's
// plane (clip includes the reflection, eye is the reflected eye, and what lies
// behind the plane is clipped away).
struct View {
  gl::framebuffer* target = nullptr;
  ClipFromWorld clip;
  PointWorld eye;
  bool through_mirror = false;
  // Towards the camera. Without a mirror zero, so that nothing is clipped even
  // where a driver (llvmpipe) applies gl_ClipDistance with GL_CLIP_DISTANCE0 off.
  NormalWorld plane_normal = sg::from_raw<NormalWorld>(glm::vec3(0.0f));
  PointWorld plane_point;
  int skip_shape = -1;       // the mirror itself
};

// One planar mirror: its plane in object space and the target its reflection
// pass renders into, every pass anew.
struct MirrorTarget {
  int shape;
  Plane plane;
  gl::texture2d<Radiance> image;
  gl::framebuffer target;
  std::optional<View> view;  // this pass's; empty when the camera sees its plane edge-on
  MirrorTarget(int s, Plane p, int width, int height, const gl::output_id<Radiance>& radiance)
      : shape(s), plane(p), image(width, height), target(width, height) {
    target.attach(radiance, image);
    target.add_depth();
  }
};

// The reflection across the plane through `point` with unit normal `n`: x − 2 n (n · (x − point)).
glm::mat4 reflection_across(glm::vec3 point, glm::vec3 n) {
  glm::mat4 m(1.0f);
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) m[c][r] -= 2 * n[r] * n[c];
  m[3] = glm::vec4(2 * glm::dot(n, point) * n, 1.0f);
  return m;
}

// A cube shadow map: six faces of distances in one 3 x 2 texture.
struct ShadowCube {
  int face_texels;
  gl::texture2d<Length> distances;
  gl::framebuffer target;
  std::array<LightClipFromWorld, 6> clip_from_world;
  ShadowCube(int texels, const DepthPass& depth)
      : face_texels(texels), distances(3 * texels, 2 * texels), target(3 * texels, 2 * texels) {
    target.attach(depth.distance, distances);
    target.add_depth();
  }
};

// Axis, and up vector, of cube face f (+x, −x, +y, −y, +z, −z).
const glm::vec3 kFaceAxis[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
const glm::vec3 kFaceUp[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};

// Whether any direction in face f's frustum leaves the emitter's front side.
bool face_sees_front(int face, glm::vec3 emitter_normal) {
  glm::vec3 a = kFaceAxis[face], u = kFaceUp[face], v = glm::cross(a, u);
  float best = -INFINITY;
  for (float su : {-1.0f, 1.0f})
    for (float sv : {-1.0f, 1.0f}) best = std::max(best, glm::dot(emitter_normal, a + su * u + sv * v));
  return best > 0;
}

// Where pass p of n samples its pixels: the Halton points of bases 3 and 2,
// whose 1-D projections are stratified (base 2 exactly, for n a power of two),
// so a pixel cut by a horizontal or vertical edge is covered to within ~1/n.
glm::vec2 pixel_offset(int pass, int passes) {
  auto radical_inverse = [](uint32_t i, uint32_t base) {
    double inverse = 1.0 / base, scale = inverse, value = 0;
    for (; i > 0; i /= base, scale *= inverse) value += (i % base) * scale;
    return value;
  };
  double shift = 0.5 / passes;
  double x = radical_inverse(static_cast<uint32_t>(pass), 3) + shift, y = radical_inverse(static_cast<uint32_t>(pass), 2) + shift;
  return {static_cast<float>(x - std::floor(x)), static_cast<float>(y - std::floor(y))};
}

}  // namespace

struct Preview::Impl {
  const Scene& scene;
  PreviewOptions options;
  int width, height;
  SceneMeshes meshes;
  ScenePoses poses;
  std::vector<Emitter> emitters;
  std::vector<Reflectance> pattern_means;  // per Scene::patterns: sampled once, drawn as the texture's colour
  // Per Scene::point_lights: the intensity drawn, a goniometric or projection
  // light's mean over its map (the same power), summed once.
  std::vector<Intensity> point_intensities;

  EmissionPass emission{camera_program("EMISSION", "emission", options)};
  PointLightPass point_pass{{camera_program("POINT_LIGHT", "point_light", options)}};
  AreaSamplePass area_pass{{camera_program("AREA_SAMPLE", "area_sample", options)}};
  MirrorPass mirror_pass{camera_program("MIRROR", "mirror", options)};
  DepthPass depth{load_embedded_program({"shadow_depth.sgl.vert", "shadow_depth.sgl.frag"}, {}, "shadow_depth",
                                        format_of(options))};

  gl::vertex_buffer<PointObject> positions{std::span<const PointObject>(meshes.positions)};
  gl::vertex_buffer<normal<Object>> normals{std::span<const normal<Object>>(meshes.normals)};
  gl::vertex_array camera_geometry, light_geometry;

  gl::texture2d<Radiance> accumulation{width, height};
  gl::framebuffer frame{width, height};
  std::vector<ShadowCube> point_shadows;
  std::optional<ShadowCube> area_shadow;
  bool point_shadows_valid = false;
  std::vector<MirrorTarget> mirrors;     // planar mirrors, reflected one bounce
  std::vector<std::string> curved_mirrors;  // mirrors drawn black: not planar
  std::vector<std::string> approximations;  // Preview::approximations()
  FrameStats stats;

  Impl(const Scene& s, PreviewOptions o)
      : scene(s),
        options(o),
        width(o.width > 0 ? o.width : s.settings.width),
        height(o.height > 0 ? o.height : s.settings.height),
        meshes(tessellate(s)),
        poses(s),
        emitters(emitters_of(s)) {
    for (const ProceduralTexture& texture : scene.patterns) pattern_means.push_back(mean_value(texture.pattern));
    for (const PointLight& light : scene.point_lights)
      point_intensities.push_back(light.profile ? light.intensity * mean_intensity_factor(*light.profile) : light.intensity);
    camera_geometry.bind(emission.program.attribute<PointObject>("position"), positions);
    camera_geometry.bind(emission.program.attribute<normal<Object>>("objectNormal"), normals);
    light_geometry.bind(depth.program.attribute<PointObject>("position"), positions);
    frame.attach(emission.radiance, accumulation);
    frame.add_depth();
    for (size_t i = 0; i < scene.point_lights.size() + scene.spot_lights.size(); ++i)
      point_shadows.emplace_back(options.shadow_resolution, depth);
    if (!emitters.empty() && options.area_shadows) area_shadow.emplace(options.area_shadow_resolution, depth);
    for (size_t s = 0; s < scene.shapes.size(); ++s) {
      const Shape& shape = scene.shapes[s];
      if (shape.material < 0 || !std::holds_alternative<MirrorMaterial>(scene.materials[shape.material].model)) continue;
      if (std::optional<Plane> plane = plane_of(shape))
        mirrors.emplace_back(static_cast<int>(s), *plane, width, height, emission.radiance);
      else
        curved_mirrors.push_back(shape_name(s));
    }
    describe_approximations();
  }

  std::string shape_name(size_t s) const {
    return scene.shapes[s].name.empty() ? "shapes[" + std::to_string(s) + "]" : scene.shapes[s].name;
  }

  // Said on stderr and in the image files: what the preview does not model.
  void describe_approximations() {
    auto names_of = [&](auto&& selected) {
      std::string names;
      for (size_t s = 0; s < scene.shapes.size(); ++s)
        if (scene.shapes[s].material >= 0 && selected(scene.materials[scene.shapes[s].material]))
          names += (names.empty() ? "" : ", ") + shape_name(s);
      return names;
    };
    auto add = [&](const std::string& names, const std::string& phrase) {
      if (!names.empty()) approximations.push_back(phrase + " (" + names + ")");
    };
    if (!curved_mirrors.empty()) {
      std::string names;
      for (const std::string& name : curved_mirrors) names += (names.empty() ? "" : ", ") + name;
      approximations.push_back("curved mirrors are not previewed and appear black (" + names +
                               "); planar mirrors show one-bounce reflections");
    }
    // Rough glass is a translucent material without a diffuse part.
    auto rough_glass = [](const Material& m) {
      const auto* translucent = std::get_if<TranslucentMaterial>(&m.model);
      return translucent && sg::is_black(translucent->diffuse.value);
    };
    add(names_of([&](const Material& m) { return std::holds_alternative<GlassMaterial>(m.model) || rough_glass(m); }),
        "glass is not previewed and appears black");
    add(names_of([](const Material& m) { return std::holds_alternative<ConductorMaterial>(m.model); }),
        "metal is not previewed and appears black");
    add(names_of([](const Material& m) { return std::holds_alternative<OrenNayarMaterial>(m.model); }),
        "rough diffuse (Oren-Nayar) surfaces are drawn as Lambertian");
    add(names_of([](const Material& m) { return std::holds_alternative<PlasticMaterial>(m.model); }),
        "plastic is drawn as its diffuse layer, without its coating's reflection");
    add(names_of([](const Material& m) { return std::holds_alternative<SubstrateMaterial>(m.model); }),
        "substrate is drawn as its diffuse layer (Kd), without its coating's reflection");
    add(names_of([&](const Material& m) { return std::holds_alternative<TranslucentMaterial>(m.model) && !rough_glass(m); }),
        "translucent is drawn as its diffuse reflection (reflect times Kd), without its glossy lobes or the light it "
        "lets through");
    add(names_of([](const Material& m) { return std::holds_alternative<DisneyMaterial>(m.model); }),
        "disney is drawn as its diffuse part ((1 - metallic)(1 - spectrans) times its colour) as Lambert, without its "
        "specular, sheen or clearcoat reflection or the light it lets through");
    add(names_of([](const Material& m) { return m.mix.has_value(); }),
        "mix materials are drawn as their parts' diffuse and Phong colours weighted by the amount, mirrors, glass "
        "and metal among them as black");
    add(names_of([](const Material& m) { return diffuse_of(m) && diffuse_of(m)->textured(); }),
        "textures are drawn as their mean colour");
    std::string masked;
    for (size_t s = 0; s < scene.shapes.size(); ++s)
      if (scene.shapes[s].alpha || scene.shapes[s].shadow_alpha) masked += (masked.empty() ? "" : ", ") + shape_name(s);
    add(masked, "alpha masks are not previewed: masked surfaces are drawn whole");
    std::string mapped;
    for (size_t i = 0; i < scene.point_lights.size(); ++i)
      if (scene.point_lights[i].profile) mapped += (mapped.empty() ? "" : ", ") + ("point_lights[" + std::to_string(i) + "]");
    add(mapped, "goniometric and projection lights are drawn as point lights of their mean intensity, without their map");
    if (scene.environment) approximations.push_back("the environment light is not previewed (no light from it)");
    if (!scene.distant_lights.empty()) approximations.push_back("distant lights are not previewed (no light from them)");
  }

  // The diffuse reflectance a surface is drawn with: a texture by its mean.
  Reflectance preview_diffuse(const TexturedReflectance& diffuse) const {
    if (diffuse.pattern >= 0) return diffuse.value * pattern_means[diffuse.pattern];
    if (diffuse.texture < 0) return diffuse.value;
    return diffuse.value * scene.textures[diffuse.texture].mipmap->average();
  }

  // What the light passes draw a material with: a diffuse part and a Phong
  // lobe. None for mirrors (a delta BRDF gets no direct light; planar ones
  // reflect in draw_mirrors), glass, metal and black.
  struct LitSurface {
    Reflectance kd, ks;
    float exponent = 1.0f;
  };
  // A mix: its parts' diffuse and Phong parts weighted by the amount (a
  // texture's by its mean); the exponent of the glossier part.
  std::optional<LitSurface> lit_mix(const MaterialMix& mix) const {
    const Reflectance amount = preview_diffuse(mix.amount);
    const Reflectance weights[2] = {amount, Reflectance(1.0f) - amount};
    const int parts[2] = {mix.first, mix.second};
    std::optional<LitSurface> sum;
    for (int i = 0; i < 2; ++i) {
      if (parts[i] < 0) continue;
      const std::optional<LitSurface> part = lit_surface(scene.materials[parts[i]]);
      if (!part) continue;
      if (!sum) sum = LitSurface{Reflectance{}, Reflectance{}, part->exponent};
      if (sg::max_component(weights[i] * part->ks) > sg::max_component(sum->ks)) sum->exponent = part->exponent;
      sum->kd = sum->kd + weights[i] * part->kd;
      sum->ks = sum->ks + weights[i] * part->ks;
    }
    return sum;
  }

  std::optional<LitSurface> lit_surface(const Material& material) const {
    using Lit = std::optional<LitSurface>;
    if (material.mix) return lit_mix(*material.mix);
    return std::visit(Overloaded{[&](const LambertMaterial& m) -> Lit { return LitSurface{preview_diffuse(m.diffuse), {}}; },
                                 [&](const OrenNayarMaterial& m) -> Lit { return LitSurface{preview_diffuse(m.diffuse), {}}; },
                                 [&](const PhongMaterial& m) -> Lit {
                                   return LitSurface{preview_diffuse(m.diffuse), m.specular, m.exponent};
                                 },
                                 [&](const PlasticMaterial& m) -> Lit { return LitSurface{preview_diffuse(m.diffuse), {}}; },
                                 [&](const SubstrateMaterial& m) -> Lit { return LitSurface{preview_diffuse(m.diffuse), {}}; },
                                 [&](const DisneyMaterial& m) -> Lit {
                                   return LitSurface{preview_diffuse(m.diffuse) * ((1 - m.metallic) * (1 - m.spec_trans)), {}};
                                 },
                                 [&](const TranslucentMaterial& m) -> Lit {
                                   return LitSurface{preview_diffuse(m.diffuse) * m.reflect, {}};
                                 },
                                 [](const MirrorMaterial&) -> Lit { return std::nullopt; },
                                 [](const GlassMaterial&) -> Lit { return std::nullopt; },
                                 [](const ConductorMaterial&) -> Lit { return std::nullopt; },
                                 [](const BlackMaterial&) -> Lit { return std::nullopt; }},
                      material.model);
  }

  // The point-like lights: point lights, then spot lights, with their cones.
  size_t point_like_count() const { return scene.point_lights.size() + scene.spot_lights.size(); }
  PointWorld point_like_position(size_t i) const {
    return i < scene.point_lights.size() ? scene.point_lights[i].position
                                         : scene.spot_lights[i - scene.point_lights.size()].position;
  }

  Length near_distance() const { return poses.bounds_radius() * 1e-4f; }

  ClipFromWorld clip_from_world(glm::vec2 jitter, const glm::mat4& reflection = glm::mat4(1.0f)) const {
    const Camera& camera = scene.camera;
    float tangent = std::tan(0.5f * sg::raw(camera.fov));
    float shorter = static_cast<float>(std::min(width, height));
    float fov_y = 2 * std::atan(tangent * static_cast<float>(height) / shorter);
    Length far = sg::length(camera.position - poses.bounds_center()) + 2.0f * poses.bounds_radius();
    glm::mat4 view = glm::lookAt(sg::raw(camera.position), sg::raw(camera.look_at), sg::raw(camera.up));
    glm::mat4 projection = glm::perspective(fov_y, static_cast<float>(width) / static_cast<float>(height),
                                            sg::raw(near_distance()), sg::raw(far));
    // Moves the image by a fraction of a pixel: passes sample the pixel's area like the CPU renderer's box filter.
    glm::mat4 shift = glm::translate(glm::mat4(1.0f), glm::vec3((2 * jitter.x - 1) / static_cast<float>(width),
                                                                 (2 * jitter.y - 1) / static_cast<float>(height), 0));
    return ClipFromWorld::from_matrix(shift * projection * view * reflection);
  }

  void set_cube_faces(ShadowCube& cube, PointWorld light) const {
    Length far = sg::length(light - poses.bounds_center()) + 2.0f * poses.bounds_radius();
    glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, sg::raw(near_distance()), sg::raw(far));
    glm::vec3 eye = sg::raw(light);
    for (int f = 0; f < 6; ++f)
      cube.clip_from_world[f] =
          LightClipFromWorld::from_matrix(projection * glm::lookAt(eye, eye + kFaceAxis[f], kFaceUp[f]));
  }

  // Distances from `light` to the nearest surface, on the faces `faces` lets through.
  template <class FaceFilter>
  void render_shadow_cube(ShadowCube& cube, PointWorld light, Time time, int skip_shape, FaceFilter faces) {
    set_cube_faces(cube, light);
    cube.target.bind();
    glDisable(GL_CLIP_DISTANCE0);  // the depth pass's vertex shader writes no clip distance
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    const float far[4] = {kFarDistance, kFarDistance, kFarDistance, kFarDistance};
    glClearBufferfv(GL_COLOR, 0, far);
    glClear(GL_DEPTH_BUFFER_BIT);
    depth.program.use();
    depth.program.set(depth.light_position, light);
    for (int f = 0; f < 6; ++f) {
      if (!faces(f)) continue;
      glViewport((f % 3) * cube.face_texels, (f / 3) * cube.face_texels, cube.face_texels, cube.face_texels);
      depth.program.set(depth.light_clip_from_world, cube.clip_from_world[f]);
      for (size_t s = 0; s < scene.shapes.size(); ++s) {
        if (static_cast<int>(s) == skip_shape || meshes.ranges[s].count == 0) continue;
        depth.program.set(depth.world_from_object, poses.at(s, time));
        light_geometry.draw_triangles(meshes.ranges[s].first, meshes.ranges[s].count);
        ++stats.draw_calls;
      }
      ++stats.shadow_faces;
    }
  }

  // Starts a pass in a view's target: depth cleared, colour kept (but on the
  // first pass; a mirror's target starts empty every pass).
  void begin_camera_pass(const View& view, bool clear_colour) {
    view.target->bind();
    set_clipping(view);
    if (clear_colour) {
      const float zero[4] = {0, 0, 0, 0};
      glClearBufferfv(GL_COLOR, 0, zero);
    }
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
  }

  static void set_clipping(const View& view) {
    if (view.through_mirror) glEnable(GL_CLIP_DISTANCE0);
    else glDisable(GL_CLIP_DISTANCE0);
  }

  // Back to a view's target after a shadow map, keeping the pass's depth:
  // light passes add onto the surfaces the emission pass found nearest.
  void resume_lighting(const View& view) {
    view.target->bind();
    set_clipping(view);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
  }

  void set_camera(const CameraHandles& handles, const gl::Program& program, const View& view) const {
    program.set(handles.clip_from_world, view.clip);
    program.set(handles.eye, view.eye);
    program.set(handles.clip_normal, view.plane_normal);
    program.set(handles.clip_point, view.plane_point);
  }

  // Emitters seen directly, and the depth every light pass then shades exactly.
  void draw_emission(const View& view, Time time) {
    glDepthFunc(GL_LESS);
    emission.program.use();
    set_camera(emission.camera, emission.program, view);
    for (size_t s = 0; s < scene.shapes.size(); ++s) {
      if (static_cast<int>(s) == view.skip_shape) continue;
      const Shape& shape = scene.shapes[s];
      emission.program.set(emission.le, shape.emission ? *shape.emission : Radiance{});
      emission.program.set(emission.two_sided, int32_t{shape.two_sided_emission});
      emission.program.set(emission.camera.world_from_object, poses.at(s, time));
      camera_geometry.draw_triangles(meshes.ranges[s].first, meshes.ranges[s].count);
      ++stats.draw_calls;
    }
    resume_lighting(view);
  }

  // Every lit surface once, shaded by the light the pass's uniforms hold, in
  // every view (the camera's and each mirror's).
  void draw_lit_surfaces(const LightPass& pass, const ShadowCube& cube, const std::vector<View>& views, Time time) {
    for (const View& view : views) {
      resume_lighting(view);
      draw_lit_surfaces(pass, cube, view, time);
    }
  }
  void draw_lit_surfaces(const LightPass& pass, const ShadowCube& cube, const View& view, Time time) {
    pass.program.use();
    set_camera(pass.camera, pass.program, view);
    pass.program.bind(pass.shadow_map, cube.distances, 0);
    pass.program.set(pass.shadow_clip_from_world, cube.clip_from_world);
    pass.program.set(pass.face_texels, static_cast<float>(cube.face_texels));
    pass.program.set(pass.bias_texels, options.shadow_bias_texels);
    for (size_t s = 0; s < scene.shapes.size(); ++s) {
      const Shape& shape = scene.shapes[s];
      if (shape.material < 0 || static_cast<int>(s) == view.skip_shape) continue;
      std::optional<LitSurface> surface = lit_surface(scene.materials[shape.material]);
      if (!surface) continue;
      pass.program.set(pass.kd, surface->kd);
      pass.program.set(pass.ks, surface->ks);
      pass.program.set(pass.exponent, surface->exponent);
      pass.program.set(pass.camera.world_from_object, poses.at(s, time));
      camera_geometry.draw_triangles(meshes.ranges[s].first, meshes.ranges[s].count);
      ++stats.draw_calls;
    }
  }

  void draw_point_lights(const std::vector<View>& views, Time time) {
    for (size_t i = 0; i < point_like_count(); ++i) {
      if (i < scene.point_lights.size()) {
        const PointLight& light = scene.point_lights[i];
        point_pass.program.set(point_pass.light_position, light.position);
        point_pass.program.set(point_pass.intensity, point_intensities[i]);
        point_pass.program.set(point_pass.spot_cos_total, -2.0f);  // every direction inside the "cone"
        point_pass.program.set(point_pass.spot_cos_start, -2.0f);
      } else {
        const SpotLight& light = scene.spot_lights[i - scene.point_lights.size()];
        point_pass.program.set(point_pass.light_position, light.position);
        point_pass.program.set(point_pass.intensity, light.intensity);
        point_pass.program.set(point_pass.spot_axis, light.direction);
        point_pass.program.set(point_pass.spot_cos_total, sg::cos(light.cone_angle));
        point_pass.program.set(point_pass.spot_cos_start, sg::cos(light.cone_angle - light.cone_delta));
      }
      draw_lit_surfaces(point_pass, point_shadows[i], views, time);
    }
  }

  void draw_area_lights(const std::vector<View>& views, Time time, int pass_index) {
    if (emitters.empty()) return;
    const int n = std::max(1, options.light_samples);
    // Without shadows, a map that holds only "far" lets every point see the light.
    if (!area_shadow) {
      area_shadow.emplace(1, depth);
      render_shadow_cube(*area_shadow, scene.camera.position, time, -1, [](int) { return false; });
    }
    for (const Emitter& still : emitters) {
      // A moving emitter is sampled where it is at this shutter time, as the CPU renderer does.
      const int shape = still.shape();
      const Emitter emitter = poses.moves(shape) ? Emitter(scene, shape, poses.at(shape, time)) : still;
      area_pass.program.set(area_pass.le, emitter.radiance());
      area_pass.program.set(area_pass.sample_area, emitter.area() / static_cast<float>(n));
      area_pass.program.set(area_pass.two_sided, int32_t{emitter.two_sided()});
      for (int k = 0; k < n; ++k) {
        float u1, u2;
        r2_point(static_cast<uint32_t>(pass_index * n + k), u1, u2);
        EmitterPoint y = emitter.sample(u1, u2);
        if (options.area_shadows) {
          glm::vec3 front = sg::raw(y.normal);
          render_shadow_cube(*area_shadow, y.position, time, emitter.shape(),
                             [&](int f) { return emitter.two_sided() || face_sees_front(f, front); });
        }
        area_pass.program.set(area_pass.light_position, y.position);
        area_pass.program.set(area_pass.emitter_normal, y.normal);
        draw_lit_surfaces(area_pass, *area_shadow, views, time);
        ++stats.area_samples;
      }
    }
  }

  // The camera seen through `mirror`'s plane at `time`; none when the camera
  // lies in the plane.
  std::optional<View> mirror_view(MirrorTarget& mirror, glm::vec2 jitter, Time time) const {
    RenderFromObject pose = poses.at(mirror.shape, time);
    PointWorld point = pose(mirror.plane.point);
    NormalWorld normal = pose(mirror.plane.unit_normal);  // renormalised by the map
    Length height = sg::dot(normal, scene.camera.position - point);
    if (height == sg::zero) return std::nullopt;
    if (height < sg::zero) {
      normal = -normal;  // mirrors are two-sided: the side the camera is on reflects
      height = -height;
    }
    glm::vec3 n = sg::raw(normal);
    View view;
    view.target = &mirror.target;
    view.clip = clip_from_world(jitter, reflection_across(sg::raw(point), n));
    view.eye = sg::from_raw<PointWorld>(sg::raw(scene.camera.position) - 2 * sg::raw(height) * n);
    view.through_mirror = true;
    view.plane_normal = normal;
    view.plane_point = point;
    view.skip_shape = mirror.shape;
    return view;
  }

  // Each planar mirror's surface, Kr times its reflection pass, added where the camera sees it.
  void draw_mirrors(const View& camera_view, Time time) {
    if (mirrors.empty()) return;
    resume_lighting(camera_view);
    mirror_pass.program.use();
    set_camera(mirror_pass.camera, mirror_pass.program, camera_view);
    for (const MirrorTarget& mirror : mirrors) {
      if (!mirror.view) continue;
      mirror_pass.program.bind(mirror_pass.reflection, mirror.image, 0);
      mirror_pass.program.set(mirror_pass.kr,
                              std::get<MirrorMaterial>(scene.materials[scene.shapes[mirror.shape].material].model).reflectance);
      mirror_pass.program.set(mirror_pass.camera.world_from_object, poses.at(mirror.shape, time));
      camera_geometry.draw_triangles(meshes.ranges[mirror.shape].first, meshes.ranges[mirror.shape].count);
      ++stats.draw_calls;
      ++stats.mirror_views;
    }
  }

  render::Image render() {
    stats = {};
    const int passes = std::max(1, options.passes);
    const Camera& camera = scene.camera;
    for (int p = 0; p < passes; ++p) {
      float stratum = (static_cast<float>(p) + 0.5f) / static_cast<float>(passes);
      Time time = camera.shutter_open + (camera.shutter_close - camera.shutter_open) * stratum;
      glm::vec2 jitter = passes > 1 ? pixel_offset(p, passes) : glm::vec2(0.5f);
      if (!point_shadows_valid || poses.animated() || options.refresh_shadows) {
        for (size_t i = 0; i < point_like_count(); ++i)
          render_shadow_cube(point_shadows[i], point_like_position(i), time, -1, [](int) { return true; });
        point_shadows_valid = true;
      }
      View camera_view;
      camera_view.target = &frame;
      camera_view.clip = clip_from_world(jitter);
      camera_view.eye = camera.position;
      std::vector<View> views{camera_view};
      begin_camera_pass(camera_view, p == 0);
      draw_emission(camera_view, time);
      for (MirrorTarget& mirror : mirrors) {
        mirror.view = mirror_view(mirror, jitter, time);
        if (!mirror.view) continue;
        begin_camera_pass(*mirror.view, true);
        draw_emission(*mirror.view, time);
        views.push_back(*mirror.view);
      }
      draw_point_lights(views, time);
      draw_area_lights(views, time, p);
      draw_mirrors(camera_view, time);
      ++stats.passes;
    }
    std::vector<Radiance> texels = accumulation.read_back();
    render::Image image{width, height, std::vector<float>(3 * static_cast<size_t>(width) * height)};
    const float scale = 1.0f / static_cast<float>(passes);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        glm::vec3 value = sg::raw(texels[static_cast<size_t>(height - 1 - y) * width + x]) * scale;
        float* out = image.pixel(x, y);
        out[0] = value.x, out[1] = value.y, out[2] = value.z;
      }
    return image;
  }
};

namespace {
// The rasteriser draws through a pinhole; the other cameras are the path tracer's.
const Scene& with_perspective_camera(const Scene& scene) {
  if (scene.camera.projection != render::CameraProjection::perspective)
    throw std::invalid_argument(
        std::string("the preview draws perspective cameras only, and this scene's is ") +
        (scene.camera.projection == render::CameraProjection::orthographic ? "orthographic" : "an environment camera") +
        ": render it with safegi-render");
  return scene;
}
}  // namespace

Preview::Preview(const render::Scene& scene, PreviewOptions options)
    : impl_(std::make_unique<Impl>(with_perspective_camera(scene), options)) {}
Preview::~Preview() = default;

render::Image Preview::render(FrameStats* stats) {
  render::Image image = impl_->render();
  if (stats) *stats = impl_->stats;
  return image;
}

int Preview::width() const { return impl_->width; }
const std::vector<std::string>& Preview::curved_mirrors() const { return impl_->curved_mirrors; }
const std::vector<std::string>& Preview::approximations() const { return impl_->approximations; }
int Preview::height() const { return impl_->height; }

}  // namespace safegi::preview
