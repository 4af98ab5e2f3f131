// Sanitizer builds of the Vulkan tests only. Mesa's lavapipe keeps 128 bytes
// per VkInstance reachable from one of its globals; when the loader dlcloses
// the driver at vkDestroyInstance, LeakSanitizer finds that memory without an
// owner and cannot even name the module it came from (it is unmapped by
// then). Keeping the driver loaded for the whole process (RTLD_NODELETE)
// leaves the memory reachable, so no suppression is needed and every other
// leak is still reported. Elsewhere (an NVIDIA driver) the dlopen simply fails.
// A GoogleTest environment, so listing the tests (gtest_discover_tests at
// build time) does not load the driver.
#include <dlfcn.h>
#include <gtest/gtest.h>

namespace {

class KeepLavapipeLoaded : public ::testing::Environment {
 public:
  void SetUp() override { dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_NODELETE); }
};
::testing::Environment* const keep_lavapipe_loaded = ::testing::AddGlobalTestEnvironment(new KeepLavapipeLoaded);

}  // namespace
