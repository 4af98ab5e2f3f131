#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <algorithm>
#include <map>
#include <mutex>
#include <vector>

#include "platform.hpp"

namespace safegi::gl {
namespace {

bool has_extension(const char* list, std::string_view name) {
  if (!list) return false;
  std::string_view all(list);
  for (std::size_t start = 0; start < all.size();) {
    std::size_t end = all.find(' ', start);
    if (end == std::string_view::npos) end = all.size();
    if (all.substr(start, end - start) == name) return true;
    start = end + 1;
  }
  return false;
}

std::string egl_error_name(EGLint error) {
  switch (error) {
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    default: return "EGL error " + std::to_string(error);
  }
}

// EGL displays are per-process singletons shared by every context on them;
// terminate one only when its last context is gone.
class DisplayUses {
 public:
  void acquire(EGLDisplay display) {
    std::lock_guard lock(mutex_);
    ++uses_[display];
  }
  void release(EGLDisplay display) {
    std::lock_guard lock(mutex_);
    if (--uses_[display] == 0) {
      uses_.erase(display);
      eglTerminate(display);
    }
  }

 private:
  std::mutex mutex_;
  std::map<EGLDisplay, int> uses_;
};

DisplayUses& display_uses() {
  static DisplayUses uses;
  return uses;
}

class EglBackend final : public Context::Backend {
 public:
  EglBackend(EGLDisplay display, EGLContext context) : display_(display), context_(context) {}
  ~EglBackend() override {
    if (eglGetCurrentContext() == context_) eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    display_uses().release(display_);
  }
  bool make_current() override { return eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_); }
  GetProcAddress loader() const override {
    return [](const char* name) { return reinterpret_cast<GlProc>(eglGetProcAddress(name)); };
  }

 private:
  EGLDisplay display_;
  EGLContext context_;
};

// Initializes `display` and creates a current, surfaceless core context on it.
std::unique_ptr<EglBackend> create_on_display(EGLDisplay display, int major, int minor, const std::string& label,
                                              std::string& why) {
  if (display == EGL_NO_DISPLAY) {
    why += "  " + label + ": no display (" + egl_error_name(eglGetError()) + ")\n";
    return nullptr;
  }
  EGLint egl_major = 0, egl_minor = 0;
  if (!eglInitialize(display, &egl_major, &egl_minor)) {
    why += "  " + label + ": eglInitialize failed (" + egl_error_name(eglGetError()) + ")\n";
    return nullptr;
  }
  display_uses().acquire(display);
  auto fail = [&](const std::string& reason) -> std::unique_ptr<EglBackend> {
    why += "  " + label + ": " + reason + '\n';
    display_uses().release(display);
    return nullptr;
  };
  if (!has_extension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context"))
    return fail("the display lacks EGL_KHR_surfaceless_context");
  if (!eglBindAPI(EGL_OPENGL_API)) return fail("eglBindAPI(EGL_OPENGL_API) failed");

  const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (!eglChooseConfig(display, config_attributes, &config, 1, &count) || count == 0) {
    if (!has_extension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context"))
      return fail("no OpenGL-renderable EGLConfig");
    config = nullptr;  // EGL_NO_CONFIG_KHR
  }
  const int versions[][2] = {{major, minor}, {3, 3}};
  for (const auto& version : versions) {
    const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, version[0],
                                         EGL_CONTEXT_MINOR_VERSION, version[1],
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
    if (context == EGL_NO_CONTEXT) continue;
    auto backend = std::make_unique<EglBackend>(display, context);
    if (!backend->make_current()) {
      why += "  " + label + ": eglMakeCurrent failed (" + egl_error_name(eglGetError()) + ")\n";
      return nullptr;  // the backend's destructor releases the display
    }
    return backend;
  }
  return fail("eglCreateContext gave no core context of version " + std::to_string(major) + '.' +
              std::to_string(minor) + " or 3.3 (" + egl_error_name(eglGetError()) + ')');
}

template <class Function>
Function egl_function(const char* name) {
  return reinterpret_cast<Function>(eglGetProcAddress(name));
}

struct Device {
  EGLDeviceEXT handle;
  std::string extensions;
  bool software;
};

std::vector<Device> enumerate_devices(std::string& why) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_extension(client, "EGL_EXT_device_enumeration") || !has_extension(client, "EGL_EXT_platform_device")) {
    why += "  egl-device: EGL_EXT_device_enumeration or EGL_EXT_platform_device is missing\n";
    return {};
  }
  auto query_devices = egl_function<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  auto query_string = egl_function<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  EGLDeviceEXT handles[16];
  EGLint count = 0;
  if (!query_devices || !query_string || !query_devices(16, handles, &count) || count == 0) {
    why += "  egl-device: no EGL device found\n";
    return {};
  }
  std::vector<Device> devices;
  for (EGLint i = 0; i < count; ++i) {
    const char* extensions = query_string(handles[i], EGL_EXTENSIONS);
    devices.push_back({handles[i], extensions ? extensions : "",
                       has_extension(extensions, "EGL_MESA_device_software")});
  }
  // Hardware devices first, keeping the driver's order otherwise.
  std::stable_partition(devices.begin(), devices.end(), [](const Device& d) { return !d.software; });
  return devices;
}

}  // namespace

std::unique_ptr<Context::Backend> create_egl_device_backend(int major, int minor, DeviceChoice choice,
                                                            std::string& why) {
  std::vector<Device> devices = enumerate_devices(why);
  bool tried = false;
  for (std::size_t i = 0; i < devices.size(); ++i) {
    const Device& device = devices[i];
    if (device.software && choice == DeviceChoice::hardware_only) continue;
    tried = true;
    std::string label = "egl-device " + std::to_string(i) + (device.software ? " (software)" : " (hardware)");
    EGLDisplay display = eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device.handle, nullptr);
    if (auto backend = create_on_display(display, major, minor, label, why)) {
      backend->platform = Platform::egl_device;
      backend->device = label + (device.extensions.empty() ? "" : ": " + device.extensions);
      backend->software_device = device.software;
      return backend;
    }
  }
  if (!tried && !devices.empty()) why += "  egl-device: no hardware device (only software ones)\n";
  return nullptr;
}

std::unique_ptr<Context::Backend> create_egl_surfaceless_backend(int major, int minor, std::string& why) {
  if (!has_extension(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS), "EGL_MESA_platform_surfaceless")) {
    why += "  egl-surfaceless: EGL_MESA_platform_surfaceless is missing\n";
    return nullptr;
  }
  EGLDisplay display = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  auto backend = create_on_display(display, major, minor, "egl-surfaceless", why);
  if (backend) {
    backend->platform = Platform::egl_surfaceless;
    backend->device = "Mesa surfaceless platform";
    backend->software_device = false;  // decided from GL_RENDERER
  }
  return backend;
}

}  // namespace safegi::gl
