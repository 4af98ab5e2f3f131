// SPPM through the programs: safegi-render (typed) and
// safegi-render-unchecked (plain floats) render the same bits, whatever the
// thread count; its radii, areas, fluxes and densities are typed in one build
// and plain floats in the other, the same arithmetic either way.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <unistd.h>

#include "safegi/cpu_renderer/image_io.hpp"

namespace safegi::render {
namespace {

namespace fs = std::filesystem;

Image run(const char* program, const fs::path& scene, const fs::path& output, int threads) {
  const std::string command = std::string(program) + " \"" + scene.string() +
                              "\" --integrator sppm --max-depth 5 --resolution 40x30 --threads " +
                              std::to_string(threads) + " -q -o \"" + output.string() + "\"";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  return read_image(output.string() + ".exr");
}

TEST(RenderPrograms, CheckedAndUncheckedSppmImagesAreBitIdentical) {
  const fs::path directory = fs::temp_directory_path() / ("safegi-render-sppm-" + std::to_string(::getpid()));
  fs::create_directories(directory);
  const fs::path scene = fs::path(SAFEGI_SCENES_DIR) / "cornell-box" / "cornell-box.json";
  const Image checked = run(SAFEGI_RENDER_CHECKED, scene, directory / "checked", 2);
  const Image unchecked = run(SAFEGI_RENDER_UNCHECKED, scene, directory / "unchecked", 2);
  const Image one_thread = run(SAFEGI_RENDER_CHECKED, scene, directory / "one-thread", 1);
  ASSERT_EQ(checked.rgb.size(), 40u * 30u * 3u);
  ASSERT_EQ(checked.rgb.size(), unchecked.rgb.size());
  ASSERT_EQ(checked.rgb.size(), one_thread.rgb.size());
  EXPECT_EQ(std::memcmp(checked.rgb.data(), unchecked.rgb.data(), checked.rgb.size() * sizeof(float)), 0);
  EXPECT_EQ(std::memcmp(checked.rgb.data(), one_thread.rgb.data(), checked.rgb.size() * sizeof(float)), 0);
  double sum = 0;
  for (float v : checked.rgb) sum += v;
  EXPECT_GT(sum, 0);
  fs::remove_all(directory);
}

}  // namespace
}  // namespace safegi::render
