#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "safegi/cpu_renderer/image.hpp"

namespace safegi::render {
namespace {

namespace fs = std::filesystem;

std::string read_error(const fs::path& file) {
  try {
    read_pfm(file);
  } catch (const std::exception& error) {
    return error.what();
  }
  return "";
}

TEST(Pfm, AHeaderLargerThanItsFileIsRefusedBeforeAllocating) {
  fs::path file = fs::temp_directory_path() / ("safegi-pfm-" + std::to_string(::getpid()) + ".pfm");
  std::ofstream(file, std::ios::binary) << "PF\n65536 65536\n-1\n" << std::string(12, '\0');
  EXPECT_EQ(read_error(file), file.string() + ": truncated PFM file: its header says 65536x65536 pixels "
                                              "(51539607552 bytes), it holds 12 bytes of them");
  Image one{1, 1, {0.25f, 0.5f, 1.0f}};
  write_pfm(file, one);
  EXPECT_EQ(read_pfm(file).rgb, one.rgb);
  fs::remove(file);
}

}  // namespace
}  // namespace safegi::render
