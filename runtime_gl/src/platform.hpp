#pragma once
// Internal: one headless platform behind Context. Kept free of GL headers so
// that osmesa.h (which includes GL/gl.h) and glad never meet in one TU.
#include <memory>
#include <string>

#include "safegi/runtime_gl/context.hpp"

namespace safegi::gl {

using GlProc = void (*)();
using GetProcAddress = GlProc (*)(const char* name);

struct Context::Backend {
  virtual ~Backend() = default;
  virtual bool make_current() = 0;
  virtual GetProcAddress loader() const = 0;

  Platform platform = Platform::automatic;
  std::string device;
  bool software_device = true;
};

// Each returns null and appends the reason to `why` when it cannot create a
// core context of at least the requested version.
std::unique_ptr<Context::Backend> create_osmesa_backend(int major, int minor, std::string& why);
enum class DeviceChoice { hardware_only, any };
std::unique_ptr<Context::Backend> create_egl_device_backend(int major, int minor, DeviceChoice choice,
                                                            std::string& why);
std::unique_ptr<Context::Backend> create_egl_surfaceless_backend(int major, int minor, std::string& why);

}  // namespace safegi::gl
