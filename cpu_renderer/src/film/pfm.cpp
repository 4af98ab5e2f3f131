#include <algorithm>
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
  // The header is checked against the file before the raster is allocated: a
  // 20-byte file must not ask for 48 GiB.
  const std::streamoff raster_start = in.tellg();
  in.seekg(0, std::ios::end);
  const std::streamoff raster_bytes = in.tellg() - raster_start;
  in.seekg(raster_start);
  const uint64_t needed = 3 * sizeof(float) * static_cast<uint64_t>(image.width) * static_cast<uint64_t>(image.height);
  if (raster_bytes < 0 || static_cast<uint64_t>(raster_bytes) < needed)
    throw std::runtime_error(file.string() + ": truncated PFM file: its header says " + std::to_string(image.width) + "x" +
                             std::to_string(image.height) + " pixels (" + std::to_string(needed) + " bytes), it holds " +
                             std::to_string(std::max<std::streamoff>(raster_bytes, 0)) + " bytes of them");
  image.rgb.resize(3 * static_cast<size_t>(image.width) * image.height);
  for (int y = image.height - 1; y >= 0; --y)
    in.read(reinterpret_cast<char*>(image.pixel(0, y)), static_cast<std::streamsize>(3 * sizeof(float) * image.width));
  if (!in) throw std::runtime_error(file.string() + ": truncated PFM file");
  return image;
}

}  // namespace safegi::render
