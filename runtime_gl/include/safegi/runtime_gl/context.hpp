#pragma once
// Headless OpenGL contexts: OSMesa, or EGL on a device (hardware first) or on
// Mesa's surfaceless platform. A Context owns its context and makes it current
// on creation; GL objects must be destroyed before their context.
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace safegi::gl {

enum class Platform {
  automatic,        // EGL hardware device, then EGL surfaceless, then any EGL device, then OSMesa
  egl,              // EGL device (hardware first), then EGL surfaceless
  egl_device,       // EGL_EXT_platform_device only
  egl_surfaceless,  // EGL_MESA_platform_surfaceless only
  osmesa,
};

std::string_view to_string(Platform platform);
// Accepts auto, egl, egl-device, egl-surfaceless, osmesa. Throws ContextError otherwise.
Platform platform_from_string(std::string_view text);
// SAFEGI_GL_PLATFORM, or automatic when unset or empty.
Platform platform_from_environment();

struct ContextOptions {
  std::optional<Platform> platform;  // unset: platform_from_environment()
  // The core version asked for, and the most runtime_gl will use: with 3.3 it
  // keeps to 3.3 paths even on a 4.5 driver. Below it, 3.3 is the floor.
  int major = 4;
  int minor = 5;
};

struct ContextInfo {
  Platform platform = Platform::automatic;  // the platform that succeeded
  std::string device;                       // EGL device kind/extensions, or "OSMesa"
  bool software = true;                     // a software rasterizer (llvmpipe, softpipe, ...)
  std::string vendor, renderer, version, shading_language_version;
  int major = 0, minor = 0;  // the version runtime_gl uses (capped at the request)
};

// "egl-surfaceless: Mesa llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6"
std::string describe(const ContextInfo& info);

class Context {
 public:
  // Creates and makes current a core-profile context; throws ContextError
  // listing why every platform that was tried failed.
  explicit Context(ContextOptions options = {});
  ~Context();
  Context(Context&&) noexcept;
  Context& operator=(Context&&) noexcept;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  // Makes this context current on the calling thread (reloading GL entry
  // points if another context was current).
  void make_current() const;
  const ContextInfo& info() const;

  struct Backend;

 private:
  std::unique_ptr<Backend> backend_;
  ContextInfo info_;
  int cap_ = 45;
};

}  // namespace safegi::gl
