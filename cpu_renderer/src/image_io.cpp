#include "safegi/cpu_renderer/image_io.hpp"

#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace safegi::render {

namespace {

void write(const std::filesystem::path& file, const OIIO::ImageSpec& spec, OIIO::TypeDesc type, const void* pixels) {
  auto output = OIIO::ImageOutput::create(file.string());
  if (!output) throw ImageError(file.string() + ": cannot write image: " + OIIO::geterror());
  if (!output->open(file.string(), spec) || !output->write_image(type, pixels)) {
    std::string error = output->geterror();
    throw ImageError(file.string() + ": cannot write image: " + error);
  }
  output->close();
}

}  // namespace

float linear_to_srgb(float linear) {
  float v = std::clamp(std::isnan(linear) ? 0.0f : linear, 0.0f, 1.0f);
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

void write_exr(const std::filesystem::path& file, const Image& image, std::string_view description) {
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT);
  spec.attribute("compression", "zip");
  if (!description.empty()) spec.attribute("ImageDescription", std::string(description));
  write(file, spec, OIIO::TypeDesc::FLOAT, image.rgb.data());
}

void write_png(const std::filesystem::path& file, const Image& image, std::string_view description) {
  std::vector<uint8_t> bytes(image.rgb.size());
  for (size_t i = 0; i < bytes.size(); ++i)
    bytes[i] = static_cast<uint8_t>(std::lround(linear_to_srgb(image.rgb[i]) * 255.0f));
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:ColorSpace", "sRGB");
  if (!description.empty()) spec.attribute("ImageDescription", std::string(description));
  write(file, spec, OIIO::TypeDesc::UINT8, bytes.data());
}

Image read_image(const std::filesystem::path& file) {
  auto input = OIIO::ImageInput::open(file.string());
  if (!input) throw ImageError(file.string() + ": cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = input->spec();
  if (spec.nchannels < 1) throw ImageError(file.string() + ": the image has no channels");
  Image image;
  image.width = spec.width;
  image.height = spec.height;
  std::vector<float> all(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
  if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()))
    throw ImageError(file.string() + ": cannot read image: " + input->geterror());
  image.rgb.resize(static_cast<size_t>(spec.width) * spec.height * 3);
  for (size_t p = 0; p < static_cast<size_t>(spec.width) * spec.height; ++p)
    for (int c = 0; c < 3; ++c) image.rgb[3 * p + c] = all[p * spec.nchannels + (spec.nchannels >= 3 ? c : 0)];
  return image;
}

}  // namespace safegi::render
