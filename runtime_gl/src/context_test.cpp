#include "safegi/runtime_gl/context.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <optional>

#include "safegi/symbol_table/error.hpp"
#include "safegi/runtime_gl/gl.hpp"

namespace safegi::gl {
namespace {

// Creates a context on `platform`, or skips the test saying why the platform
// is unavailable here.
#define CREATE_OR_SKIP(context, platform)                                          \
  std::optional<Context> context;                                                  \
  try {                                                                            \
    context.emplace(ContextOptions{platform});                                     \
  } catch (const ContextError& error) {                                            \
    GTEST_SKIP() << "platform " << to_string(platform) << " unavailable here:\n"   \
                 << error.what();                                                  \
  }

void expect_usable(const Context& context, Platform platform) {
  const ContextInfo& info = context.info();
  std::cout << "[ context  ] " << describe(info) << " (" << info.device << ")\n";
  EXPECT_EQ(info.platform, platform);
  EXPECT_GE(info.major * 10 + info.minor, 33);
  EXPECT_FALSE(info.renderer.empty());
  EXPECT_NE(info.version.find("Core"), std::string::npos) << info.version;
  // The loader works: a clear colour round-trips through GL state.
  glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
  float colour[4] = {};
  glGetFloatv(GL_COLOR_CLEAR_VALUE, colour);
  EXPECT_EQ(colour[2], 0.75f);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(Context, OsmesaGivesACoreContext) {
  CREATE_OR_SKIP(context, Platform::osmesa);
  expect_usable(*context, Platform::osmesa);
  EXPECT_TRUE(context->info().software);
}

TEST(Context, EglSurfacelessGivesACoreContext) {
  CREATE_OR_SKIP(context, Platform::egl_surfaceless);
  expect_usable(*context, Platform::egl_surfaceless);
}

TEST(Context, EglDeviceGivesACoreContext) {
  CREATE_OR_SKIP(context, Platform::egl_device);
  expect_usable(*context, Platform::egl_device);
}

TEST(Context, AutomaticFindsAPlatform) {
  Context context(ContextOptions{Platform::automatic});
  EXPECT_GE(context.info().major * 10 + context.info().minor, 33);
}

TEST(Context, SwitchesBetweenContextsOfDifferentPlatforms) {
  CREATE_OR_SKIP(osmesa, Platform::osmesa);
  CREATE_OR_SKIP(egl, Platform::egl_surfaceless);
  for (const Context* context : {&*osmesa, &*egl, &*osmesa}) {
    context->make_current();
    glClearColor(0.5f, 0.5f, 0.5f, 1.0f);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  }
}

TEST(Context, PlatformNamesAndTheEnvironment) {
  EXPECT_EQ(platform_from_string("egl-surfaceless"), Platform::egl_surfaceless);
  EXPECT_EQ(to_string(Platform::egl_device), "egl-device");
  try {
    platform_from_string("glx");
    FAIL() << "glx accepted";
  } catch (const ContextError& error) {
    EXPECT_STREQ(error.what(),
                 "safegi::gl: unknown GL platform 'glx'; choose one with "
                 "SAFEGI_GL_PLATFORM=auto|egl|egl-device|egl-surfaceless|osmesa");
  }
  const char* saved = std::getenv("SAFEGI_GL_PLATFORM");
  const std::string previous = saved ? saved : "";
  setenv("SAFEGI_GL_PLATFORM", "osmesa", 1);
  EXPECT_EQ(platform_from_environment(), Platform::osmesa);
  unsetenv("SAFEGI_GL_PLATFORM");
  EXPECT_EQ(platform_from_environment(), Platform::automatic);
  if (saved) setenv("SAFEGI_GL_PLATFORM", previous.c_str(), 1);
}

TEST(Context, FallsBackToCore33WhenTheRequestedVersionIsRefused) {
  // No driver offers 9.9; 3.3 core is the floor every platform tries next.
  Context context(ContextOptions{Platform::osmesa, 9, 9});
  EXPECT_GE(context.info().major * 10 + context.info().minor, 33);
  EXPECT_NE(context.info().version.find("Core"), std::string::npos);
}

TEST(Context, ACore33RequestKeepsTo33) {
  Context context(ContextOptions{Platform::osmesa, 3, 3});
  EXPECT_EQ(context.info().major * 10 + context.info().minor, 33);
  EXPECT_TRUE(GLAD_GL_VERSION_3_3);
  EXPECT_FALSE(GLAD_GL_VERSION_4_1);
  EXPECT_FALSE(GLAD_GL_VERSION_4_5);
}

}  // namespace
}  // namespace safegi::gl
