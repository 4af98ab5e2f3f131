// Run with EGL's vendor list pointing nowhere (see CMakeLists.txt), so that no
// EGL platform can work: the error must say what was tried and how to choose.
#include <gtest/gtest.h>

#include "safegi/runtime_gl/context.hpp"
#include "safegi/symbol_table/error.hpp"

namespace safegi::gl {
namespace {

TEST(ContextFailure, ListsEveryAttemptAndHowToChoose) {
  try {
    Context context(ContextOptions{Platform::egl});
    FAIL() << "an EGL context without any EGL vendor";
  } catch (const ContextError& error) {
    EXPECT_STREQ(error.what(),
                 "safegi::gl: no OpenGL 4.5 (or 3.3) core context on platform 'egl':\n"
                 "  egl-device: EGL_EXT_device_enumeration or EGL_EXT_platform_device is missing\n"
                 "  egl-surfaceless: EGL_MESA_platform_surfaceless is missing\n"
                 "choose one with SAFEGI_GL_PLATFORM=auto|egl|egl-device|egl-surfaceless|osmesa");
  }
}

TEST(ContextFailure, AutomaticFallsBackToOsmesa) {
  Context context(ContextOptions{Platform::automatic});
  EXPECT_EQ(context.info().platform, Platform::osmesa);
}

}  // namespace
}  // namespace safegi::gl
