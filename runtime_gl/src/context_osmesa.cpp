#include <GL/osmesa.h>

#include <vector>

#include "platform.hpp"

namespace safegi::gl {
namespace {

// OSMesa needs a colour buffer to make a context current; all rendering goes
// to framebuffer objects, so one pixel is enough.
class OsmesaBackend final : public Context::Backend {
 public:
  explicit OsmesaBackend(OSMesaContext context) : context_(context), pixel_(4) {
    platform = Platform::osmesa;
    device = "OSMesa";
  }
  ~OsmesaBackend() override { OSMesaDestroyContext(context_); }

  bool make_current() override { return OSMesaMakeCurrent(context_, pixel_.data(), GL_UNSIGNED_BYTE, 1, 1); }
  GetProcAddress loader() const override {
    return [](const char* name) { return reinterpret_cast<GlProc>(OSMesaGetProcAddress(name)); };
  }

 private:
  OSMesaContext context_;
  std::vector<unsigned char> pixel_;
};

}  // namespace

std::unique_ptr<Context::Backend> create_osmesa_backend(int major, int minor, std::string& why) {
  const int versions[][2] = {{major, minor}, {3, 3}};
  for (const auto& version : versions) {
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, version[0],
                              OSMESA_CONTEXT_MINOR_VERSION, version[1], 0};
    if (OSMesaContext context = OSMesaCreateContextAttribs(attributes, nullptr)) {
      auto backend = std::make_unique<OsmesaBackend>(context);
      if (backend->make_current()) return backend;
      why += "  osmesa: OSMesaMakeCurrent failed\n";
      return nullptr;
    }
  }
  why += "  osmesa: OSMesaCreateContextAttribs gave no core context of version " + std::to_string(major) + '.' +
         std::to_string(minor) + " or 3.3\n";
  return nullptr;
}

}  // namespace safegi::gl
