// read_file: the bytes of a file as they are, or why it could not be read.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "safegi/diagnostics/file.hpp"

namespace safegi {
namespace {

TEST(ReadFile, GivesTheBytesAsTheyAre) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "safegi_read_file_test.bin";
  const std::string bytes("a\r\nb\0c\n", 7);
  std::ofstream(path, std::ios::binary) << bytes;
  EXPECT_EQ(read_file(path.string()), bytes);
  std::ofstream(path, std::ios::binary | std::ios::trunc).close();
  EXPECT_EQ(read_file(path.string()), "");  // empty, not unreadable
  std::filesystem::remove(path);
}

TEST(ReadFile, SaysWhyAMissingFileIsNotRead) {
  std::string error;
  EXPECT_EQ(read_file("/nonexistent/safegi/file.glsl", &error), std::nullopt);
  EXPECT_EQ(error, "No such file or directory");
}

}  // namespace
}  // namespace safegi
