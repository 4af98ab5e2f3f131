#include "loader.hpp"

#include <glad/gl.h>

#include <mutex>

namespace safegi::gl {
namespace {

std::mutex loader_mutex;
const Context::Backend* loaded_for = nullptr;
int loaded_version = 0;

}  // namespace

int load_gl_for(const Context::Backend* owner, GetProcAddress loader) {
  std::lock_guard lock(loader_mutex);
  if (owner != loaded_for || loaded_version == 0) {
    int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(loader));
    loaded_for = version ? owner : nullptr;
    loaded_version = version ? GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) : 0;
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
