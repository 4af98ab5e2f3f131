#include "safegi/preview/preview.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

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
  gl::uniform_id<ObjectToWorld> world_from_object;
  gl::uniform_id<ClipFromWorld> clip_from_world;
  gl::uniform_id<PointWorld> eye;
  explicit CameraHandles(const gl::Program& p)
      : world_from_object(p.uniform<ObjectToWorld>("worldFromObject")),
        clip_from_world(p.uniform<ClipFromWorld>("clipFromWorld")),
        eye(p.uniform<PointWorld>("eye")) {}
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

struct PointLightPass : LightPass {
  gl::uniform_id<Intensity> intensity = program.uniform<Intensity>("lightIntensity");
};

struct AreaSamplePass : LightPass {
  gl::uniform_id<Radiance> le = program.uniform<Radiance>("Le");
  gl::uniform_id<Area> sample_area = program.uniform<Area>("sampleArea");
  gl::uniform_id<NormalWorld> emitter_normal = program.uniform<NormalWorld>("emitterNormal");
  gl::uniform_id<int32_t> two_sided = program.uniform<int32_t>("emitterTwoSided");
};

struct DepthPass {
  gl::Program program;
  gl::uniform_id<ObjectToWorld> world_from_object = program.uniform<ObjectToWorld>("worldFromObject");
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

  EmissionPass emission{camera_program("EMISSION", "emission", options)};
  PointLightPass point_pass{{camera_program("POINT_LIGHT", "point_light", options)}};
  AreaSamplePass area_pass{{camera_program("AREA_SAMPLE", "area_sample", options)}};
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
  FrameStats stats;

  Impl(const Scene& s, PreviewOptions o)
      : scene(s),
        options(o),
        width(o.width > 0 ? o.width : s.settings.width),
        height(o.height > 0 ? o.height : s.settings.height),
        meshes(tessellate(s)),
        poses(s),
        emitters(emitters_of(s)) {
    camera_geometry.bind(emission.program.attribute<PointObject>("position"), positions);
    camera_geometry.bind(emission.program.attribute<normal<Object>>("objectNormal"), normals);
    light_geometry.bind(depth.program.attribute<PointObject>("position"), positions);
    frame.attach(emission.radiance, accumulation);
    frame.add_depth();
    for (size_t i = 0; i < scene.point_lights.size(); ++i) point_shadows.emplace_back(options.shadow_resolution, depth);
    if (!emitters.empty() && options.area_shadows) area_shadow.emplace(options.area_shadow_resolution, depth);
  }

  Length near_distance() const { return poses.bounds_radius() * 1e-4f; }

  ClipFromWorld clip_from_world(glm::vec2 jitter) const {
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
    return ClipFromWorld::from_matrix(shift * projection * view);
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

  // Starts a pass in the accumulation buffer: depth cleared, colour kept (but on the first pass).
  void begin_camera_pass(bool first_pass) {
    frame.bind();
    if (first_pass) {
      const float zero[4] = {0, 0, 0, 0};
      glClearBufferfv(GL_COLOR, 0, zero);
    }
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
  }

  // Back to the accumulation buffer after a shadow map, keeping the pass's depth:
  // light passes add onto the surfaces the emission pass found nearest.
  void resume_lighting() {
    frame.bind();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
  }

  void set_camera(const CameraHandles& handles, const gl::Program& program, const ClipFromWorld& clip) const {
    program.set(handles.clip_from_world, clip);
    program.set(handles.eye, scene.camera.position);
  }

  // Emitters seen directly, and the depth every light pass then shades exactly.
  void draw_emission(const ClipFromWorld& clip, Time time) {
    glDepthFunc(GL_LESS);
    emission.program.use();
    set_camera(emission.camera, emission.program, clip);
    for (size_t s = 0; s < scene.shapes.size(); ++s) {
      const Shape& shape = scene.shapes[s];
      emission.program.set(emission.le, shape.emission ? *shape.emission : Radiance{});
      emission.program.set(emission.two_sided, int32_t{shape.two_sided_emission});
      emission.program.set(emission.camera.world_from_object, poses.at(s, time));
      camera_geometry.draw_triangles(meshes.ranges[s].first, meshes.ranges[s].count);
      ++stats.draw_calls;
    }
    resume_lighting();
  }

  // Every lit surface once, shaded by the light the pass's uniforms hold.
  void draw_lit_surfaces(const LightPass& pass, const ShadowCube& cube, const ClipFromWorld& clip, Time time) {
    pass.program.use();
    set_camera(pass.camera, pass.program, clip);
    pass.program.bind(pass.shadow_map, cube.distances, 0);
    pass.program.set(pass.shadow_clip_from_world, cube.clip_from_world);
    pass.program.set(pass.face_texels, static_cast<float>(cube.face_texels));
    pass.program.set(pass.bias_texels, options.shadow_bias_texels);
    for (size_t s = 0; s < scene.shapes.size(); ++s) {
      const Shape& shape = scene.shapes[s];
      if (shape.material < 0) continue;
      const Material& material = scene.materials[shape.material];
      // Mirrors are beyond a direct-lighting preview (docs/preview.md): black.
      if (material.type != Material::Type::lambert && material.type != Material::Type::phong) continue;
      bool phong = material.type == Material::Type::phong;
      pass.program.set(pass.kd, material.diffuse);
      pass.program.set(pass.ks, phong ? material.specular : Reflectance{});
      pass.program.set(pass.exponent, phong ? material.exponent : 1.0f);
      pass.program.set(pass.camera.world_from_object, poses.at(s, time));
      camera_geometry.draw_triangles(meshes.ranges[s].first, meshes.ranges[s].count);
      ++stats.draw_calls;
    }
  }

  void draw_point_lights(const ClipFromWorld& clip, Time time) {
    for (size_t i = 0; i < scene.point_lights.size(); ++i) {
      const PointLight& light = scene.point_lights[i];
      point_pass.program.set(point_pass.light_position, light.position);
      point_pass.program.set(point_pass.intensity, light.intensity);
      draw_lit_surfaces(point_pass, point_shadows[i], clip, time);
    }
  }

  void draw_area_lights(const ClipFromWorld& clip, Time time, int pass_index) {
    if (emitters.empty()) return;
    const int n = std::max(1, options.light_samples);
    // Without shadows, a map that holds only "far" lets every point see the light.
    if (!area_shadow) {
      area_shadow.emplace(1, depth);
      render_shadow_cube(*area_shadow, scene.camera.position, time, -1, [](int) { return false; });
      resume_lighting();
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
          resume_lighting();
        }
        area_pass.program.set(area_pass.light_position, y.position);
        area_pass.program.set(area_pass.emitter_normal, y.normal);
        draw_lit_surfaces(area_pass, *area_shadow, clip, time);
        ++stats.area_samples;
      }
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
      ClipFromWorld clip = clip_from_world(jitter);
      if (!point_shadows_valid || poses.animated() || options.refresh_shadows) {
        for (size_t i = 0; i < scene.point_lights.size(); ++i)
          render_shadow_cube(point_shadows[i], scene.point_lights[i].position, time, -1, [](int) { return true; });
        point_shadows_valid = true;
      }
      begin_camera_pass(p == 0);
      draw_emission(clip, time);
      draw_point_lights(clip, time);
      draw_area_lights(clip, time, p);
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

Preview::Preview(const render::Scene& scene, PreviewOptions options)
    : impl_(std::make_unique<Impl>(scene, options)) {}
Preview::~Preview() = default;

render::Image Preview::render(FrameStats* stats) {
  render::Image image = impl_->render();
  if (stats) *stats = impl_->stats;
  return image;
}

int Preview::width() const { return impl_->width; }
int Preview::height() const { return impl_->height; }

}  // namespace safegi::preview
