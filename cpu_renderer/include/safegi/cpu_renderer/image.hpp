// A rendered image: linear RGB radiance as plain floats (W/(m2 sr)), the same
// in the checked and unchecked builds, plus PFM files for small references.
// Texture files are read into the same struct (their numbers as stored).
#pragma once

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace safegi::render {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<float> rgb;  // row-major, top row first

  float* pixel(int x, int y) { return &rgb[3 * (static_cast<size_t>(y) * width + x)]; }
  const float* pixel(int x, int y) const { return &rgb[3 * (static_cast<size_t>(y) * width + x)]; }
};

// Portable float maps ("PF", little-endian, bottom row first on disk): small,
// exact, and readable without OpenImageIO.
void write_pfm(const std::filesystem::path& file, const Image& image);
Image read_pfm(const std::filesystem::path& file);  // throws std::runtime_error

}  // namespace safegi::render
