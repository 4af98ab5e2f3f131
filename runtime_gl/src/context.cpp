#include "safegi/runtime_gl/context.hpp"

#include <glad/gl.h>

#include <array>
#include <cstdlib>
#include <utility>

#include "loader.hpp"
#include "platform.hpp"
#include "safegi/symbol_table/error.hpp"

namespace safegi::gl {
namespace {

constexpr std::array<std::pair<Platform, std::string_view>, 5> kPlatformNames{{
    {Platform::automatic, "auto"},
    {Platform::egl, "egl"},
    {Platform::egl_device, "egl-device"},
    {Platform::egl_surfaceless, "egl-surfaceless"},
    {Platform::osmesa, "osmesa"},
}};

constexpr const char* kPlatformHint =
    "choose one with SAFEGI_GL_PLATFORM=auto|egl|egl-device|egl-surfaceless|osmesa";

std::string gl_string(GLenum name) {
  const auto* text = reinterpret_cast<const char*>(glGetString(name));
  return text ? text : "";
}

bool is_software_renderer(const std::string& renderer) {
  for (const char* name : {"llvmpipe", "softpipe", "swrast", "SwiftShader", "lavapipe"})
    if (renderer.find(name) != std::string::npos) return true;
  return false;
}

std::unique_ptr<Context::Backend> create_backend(Platform platform, int major, int minor, std::string& why) {
  std::unique_ptr<Context::Backend> backend;
  auto attempt = [&](auto&& create) {
    if (!backend) backend = create();
  };
  auto hardware_device = [&] { return create_egl_device_backend(major, minor, DeviceChoice::hardware_only, why); };
  auto any_device = [&] { return create_egl_device_backend(major, minor, DeviceChoice::any, why); };
  auto surfaceless = [&] { return create_egl_surfaceless_backend(major, minor, why); };
  auto osmesa = [&] { return create_osmesa_backend(major, minor, why); };
  switch (platform) {
    case Platform::automatic:
      attempt(hardware_device);
      attempt(surfaceless);
      attempt(any_device);
      attempt(osmesa);
      break;
    case Platform::egl:
      attempt(any_device);
      attempt(surfaceless);
      break;
    case Platform::egl_device: attempt(any_device); break;
    case Platform::egl_surfaceless: attempt(surfaceless); break;
    case Platform::osmesa: attempt(osmesa); break;
  }
  return backend;
}

}  // namespace

std::string_view to_string(Platform platform) {
  for (const auto& [p, name] : kPlatformNames)
    if (p == platform) return name;
  return "?";
}

Platform platform_from_string(std::string_view text) {
  for (const auto& [platform, name] : kPlatformNames)
    if (name == text) return platform;
  throw ContextError("safegi::gl: unknown GL platform '" + std::string(text) + "'; " + kPlatformHint);
}

Platform platform_from_environment() {
  const char* value = std::getenv("SAFEGI_GL_PLATFORM");
  if (!value || !*value) return Platform::automatic;
  return platform_from_string(value);
}

std::string describe(const ContextInfo& info) {
  return std::string(to_string(info.platform)) + ": " + info.vendor + ' ' + info.renderer + ", OpenGL " +
         info.version + ", GLSL " + info.shading_language_version;
}

Context::Context(ContextOptions options) {
  Platform platform = options.platform ? *options.platform : platform_from_environment();
  std::string why;
  backend_ = create_backend(platform, options.major, options.minor, why);
  if (!backend_)
    throw ContextError("safegi::gl: no OpenGL " + std::to_string(options.major) + '.' +
                       std::to_string(options.minor) + " (or 3.3) core context on platform '" +
                       std::string(to_string(platform)) + "':\n" + why + kPlatformHint);
  cap_ = options.major * 10 + options.minor;
  int version = load_gl_for(backend_.get(), backend_->loader(), cap_);
  if (version < 33) {
    forget_gl_owner(backend_.get());
    throw ContextError("safegi::gl: the " + std::string(to_string(backend_->platform)) +
                       " context offers OpenGL " + std::to_string(version / 10) + '.' +
                       std::to_string(version % 10) + "; runtime_gl needs 3.3 core or later");
  }
  info_.platform = backend_->platform;
  info_.device = backend_->device;
  info_.major = version / 10;
  info_.minor = version % 10;
  info_.vendor = gl_string(GL_VENDOR);
  info_.renderer = gl_string(GL_RENDERER);
  info_.version = gl_string(GL_VERSION);
  info_.shading_language_version = gl_string(GL_SHADING_LANGUAGE_VERSION);
  info_.software = backend_->software_device || is_software_renderer(info_.renderer);
}

Context::~Context() {
  if (backend_) forget_gl_owner(backend_.get());
}

Context::Context(Context&&) noexcept = default;
Context& Context::operator=(Context&& other) noexcept {
  if (this != &other) {
    if (backend_) forget_gl_owner(backend_.get());
    backend_ = std::move(other.backend_);
    info_ = std::move(other.info_);
    cap_ = other.cap_;
  }
  return *this;
}

void Context::make_current() const {
  if (!backend_->make_current())
    throw ContextError("safegi::gl: could not make the " + std::string(to_string(backend_->platform)) +
                       " context current");
  load_gl_for(backend_.get(), backend_->loader(), cap_);
}

const ContextInfo& Context::info() const { return info_; }

}  // namespace safegi::gl
