// Sanitizer builds of the Vulkan tests only. Mesa's lavapipe keeps 128 bytes
// per VkInstance reachable from one of its globals; when the loader dlcloses
// the driver at vkDestroyInstance, LeakSanitizer finds that memory without an
// owner and cannot even name the module it came from (it is unmapped by
// then). Keeping the driver loaded for the whole process (RTLD_NODELETE)
// leaves the memory reachable, so no suppression is needed and every other
// leak is still reported. Elsewhere (an NVIDIA driver) the dlopen simply fails.
#include <dlfcn.h>

namespace {

struct KeepLavapipeLoaded {
  KeepLavapipeLoaded() { dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_NODELETE); }
};
const KeepLavapipeLoaded keep_lavapipe_loaded;

}  // namespace
