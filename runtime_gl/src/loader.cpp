#include "loader.hpp"

#include <glad/gl.h>

#include <mutex>

namespace safegi::gl {
namespace {

std::mutex loader_mutex;
const Context::Backend* loaded_for = nullptr;
int loaded_version = 0;

// Hides the versions above `cap` from the GLAD_GL_VERSION_* flags that
// runtime_gl tests before using newer entry points.
void cap_version(int cap) {
  int* const flags[] = {&GLAD_GL_VERSION_4_0, &GLAD_GL_VERSION_4_1, &GLAD_GL_VERSION_4_2,
                        &GLAD_GL_VERSION_4_3, &GLAD_GL_VERSION_4_4, &GLAD_GL_VERSION_4_5};
  for (int minor = 0; minor <= 5; ++minor)
    if (40 + minor > cap) *flags[minor] = 0;
}

}  // namespace

int load_gl_for(const Context::Backend* owner, GetProcAddress loader, int cap) {
  std::lock_guard lock(loader_mutex);
  if (owner != loaded_for || loaded_version == 0) {
    int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(loader));
    loaded_for = version ? owner : nullptr;
    loaded_version = version ? GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) : 0;
    if (loaded_version > cap) {
      cap_version(cap);
      loaded_version = cap;
    }
  }
  return loaded_version;
}

void forget_gl_owner(const Context::Backend* owner) {
  std::lock_guard lock(loader_mutex);
  if (owner == loaded_for) {
    loaded_for = nullptr;
    loaded_version = 0;
  }
}

}  // namespace safegi::gl
