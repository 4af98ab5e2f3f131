// Image files through OpenImageIO: EXR holds linear float radiance, PNG the
// sRGB-encoded, clamped 8-bit rendition.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include "safegi/cpu_renderer/image.hpp"

namespace safegi::render {

class ImageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// `description`, when given, goes into the file's ImageDescription (EXR
// header, PNG text chunk): what a viewer should know about the picture.
void write_exr(const std::filesystem::path& file, const Image& image, std::string_view description = {});
void write_png(const std::filesystem::path& file, const Image& image, std::string_view description = {});
// Reads any image OpenImageIO understands as floats, row 0 at the top: the first
// three channels, or grey (one or two channels) repeated into RGB; integer
// formats scaled to [0, 1] (still encoded: sRGB decoding is the caller's). The
// ImageFileReader the programs give the scene loader.
Image read_image(const std::filesystem::path& file);

// The programs' `-o render.exr` (or `render`, `render.png`, `render.pfm`) with `extension` in place
// of an image extension of theirs: each output file of one render.
inline std::filesystem::path with_image_extension(std::filesystem::path output, const char* extension) {
  const std::string ext = output.extension().string();
  if (ext == ".exr" || ext == ".png" || ext == ".pfm") output.replace_extension();
  output += extension;
  return output;
}

// The sRGB transfer function of a linear value, clamped to [0, 1].
float linear_to_srgb(float linear);

}  // namespace safegi::render
