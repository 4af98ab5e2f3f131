// EXR and PNG written without OpenImageIO, read back through its module; the
// module is loaded on the first read and not before.
#include "safegi/cpu_renderer/image_io.hpp"

#include <gtest/gtest.h>

#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace safegi::render {
namespace {

bool open_image_io_loaded() {
  std::ifstream maps("/proc/self/maps");
  std::string text((std::istreambuf_iterator<char>(maps)), std::istreambuf_iterator<char>());
  return text.find("libOpenImageIO") != std::string::npos;
}

Image gradient() {
  Image image;
  image.width = 5;
  image.height = 3;
  for (int i = 0; i < 15; ++i) image.rgb.insert(image.rgb.end(), {i * 0.1f, 1e-6f * i, 100.0f + i});
  return image;
}

class ImageIo : public testing::Test {
 protected:
  std::filesystem::path directory_ = std::filesystem::temp_directory_path() /
                                     ("safegi-image-io-" + std::to_string(::getpid()));
  void SetUp() override { std::filesystem::create_directories(directory_); }
  void TearDown() override { std::filesystem::remove_all(directory_); }
};

// One test, in order: the first read is what loads the module.
TEST_F(ImageIo, WritesWithoutOpenImageIOAndReadsBackThroughIt) {
  const Image image = gradient();
  write_exr(directory_ / "a.exr", image, "a note");
  write_png(directory_ / "a.png", image, "a note");
  EXPECT_FALSE(open_image_io_loaded()) << "writing loaded OpenImageIO";

  Imf::InputFile header_only((directory_ / "a.exr").c_str());
  const auto* note = header_only.header().findTypedAttribute<Imf::StringAttribute>("ImageDescription");
  ASSERT_NE(note, nullptr);
  EXPECT_EQ(note->value(), "a note");
  EXPECT_EQ(header_only.header().compression(), Imf::ZIP_COMPRESSION);

  const Image exr = read_image(directory_ / "a.exr");
  EXPECT_TRUE(open_image_io_loaded());
  ASSERT_EQ(exr.width, 5);
  ASSERT_EQ(exr.height, 3);
  EXPECT_EQ(exr.rgb, image.rgb);  // float EXR: every value back bit for bit

  const Image png = read_image(directory_ / "a.png");
  ASSERT_EQ(png.width, 5);
  ASSERT_EQ(png.height, 3);
  for (size_t i = 0; i < image.rgb.size(); ++i)  // 8-bit sRGB, read back still encoded
    EXPECT_NEAR(png.rgb[i], std::round(linear_to_srgb(image.rgb[i]) * 255) / 255, 1e-6f) << i;
}

TEST_F(ImageIo, FailuresNameTheFile) {
  const Image image = gradient();
  try {
    write_png(directory_ / "missing" / "a.png", image);
    FAIL() << "no error";
  } catch (const ImageError& error) {
    EXPECT_NE(std::string(error.what()).find("missing/a.png: cannot write image: "), std::string::npos) << error.what();
  }
  try {
    write_exr(directory_ / "missing" / "a.exr", image);
    FAIL() << "no error";
  } catch (const ImageError& error) {
    EXPECT_NE(std::string(error.what()).find("missing/a.exr: cannot write image: "), std::string::npos) << error.what();
  }
  std::ofstream(directory_ / "broken.png") << "not a png";
  try {
    read_image(directory_ / "broken.png");
    FAIL() << "no error";
  } catch (const ImageError& error) {
    EXPECT_NE(std::string(error.what()).find("broken.png: cannot read image: "), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace safegi::render
