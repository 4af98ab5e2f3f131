// The GL preview: direct illumination of a CPU-renderer scene with OpenGL —
// point and spot lights with cube shadow maps, area lights as many point-like
// samples with their own shadow maps, Lambert and Phong, planar mirrors with
// one-bounce reflections, motion blur by accumulating passes over the shutter. Built checked (SafeGI::preview) and unchecked
// (SafeGI::preview_unchecked) from one source. See docs/preview.md.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "safegi/cpu_renderer/image.hpp"
#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::preview {

struct PreviewOptions {
  int width = 0, height = 0;    // 0: the scene's resolution
  int light_samples = 16;       // points per area light per pass
  int passes = 1;               // shutter times and pixel positions (anti-aliasing) accumulated
  int shadow_resolution = 512;  // texels along a cube face of a point light's shadow map
  int area_shadow_resolution = 256;  // the same for each area-light sample
  float shadow_bias_texels = 1.5f;   // bias, in texel footprints (docs/preview.md)
  bool area_shadows = true;          // false: area-light samples see every point (no shadows)
  bool refresh_shadows = false;      // redraw point-light shadow maps every pass even in a static scene
  bool spirv_shaders = false;        // load the shaders as SPIR-V through GL_ARB_gl_spirv (same image)
};

struct FrameStats {
  int passes = 0;
  int area_samples = 0;       // point-like samples drawn over all passes
  int shadow_faces = 0;       // cube faces rendered into shadow maps
  int draw_calls = 0;
  int mirror_views = 0;       // planar-mirror reflections composited over all passes
};

// Needs a current runtime_gl Context for its whole life.
class Preview {
 public:
  Preview(const render::Scene& scene, PreviewOptions options);
  ~Preview();
  Preview(const Preview&) = delete;
  Preview& operator=(const Preview&) = delete;

  // One frame: every pass accumulated and averaged; linear radiance, top row first.
  render::Image render(FrameStats* stats = nullptr);
  int width() const;
  int height() const;
  // The mirrors the preview does not reflect (curved: spheres, non-planar
  // meshes), by shape name; they are drawn black.
  const std::vector<std::string>& curved_mirrors() const;
  // What this frame shows differently from the CPU renderer, one phrase each
  // (curved mirrors, glass, plastic's coating, textures, the environment
  // light), naming the shapes; empty when the preview models the whole scene.
  const std::vector<std::string>& approximations() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace safegi::preview
