#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "safegi/cpu_renderer/image.hpp"

namespace safegi::render {

void write_pfm(const std::filesystem::path& file, const Image& image) {
  std::ofstream out(file, std::ios::binary);
  if (!out) throw std::runtime_error(file.string() + ": cannot write");
  out << "PF\n" << image.width << " " << image.height << "\n-1.0\n";  // negative scale: little-endian
  for (int y = image.height - 1; y >= 0; --y)
    out.write(reinterpret_cast<const char*>(image.pixel(0, y)), static_cast<std::streamsize>(3 * sizeof(float) * image.width));
  if (!out) throw std::runtime_error(file.string() + ": cannot write");
}

Image read_pfm(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + ": cannot open");
  std::string magic;
  Image image;
  double scale = 0;
  in >> magic >> image.width >> image.height >> scale;
  in.get();  // the single whitespace before the raster
  if (!in || magic != "PF" || image.width <= 0 || image.height <= 0 || image.width > 65536 || image.height > 65536 ||
      scale >= 0)
    throw std::runtime_error(file.string() + ": not a little-endian RGB PFM file");
  image.rgb.resize(3 * static_cast<size_t>(image.width) * image.height);
  for (int y = image.height - 1; y >= 0; --y)
    in.read(reinterpret_cast<char*>(image.pixel(0, y)), static_cast<std::streamsize>(3 * sizeof(float) * image.width));
  if (!in) throw std::runtime_error(file.string() + ": truncated PFM file");
  return image;
}

}  // namespace safegi::render
