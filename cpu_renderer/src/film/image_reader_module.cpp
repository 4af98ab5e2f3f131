// OpenImageIO behind a C interface, built as a module that image_io.cpp
// loads on the first image read (see image_reader_module.hpp).
#include "film/image_reader_module.hpp"

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

namespace {

int fail(char* message, std::size_t size, const std::string& reason) {
  std::snprintf(message, size, "%s", reason.c_str());
  return 1;
}

}  // namespace

extern "C" __attribute__((visibility("default"))) int safegi_read_image_v1(const char* path, int* width, int* height,
                                                                          float** rgb, char* message,
                                                                          std::size_t message_size) {
  try {
    auto input = OIIO::ImageInput::open(path);
    if (!input) return fail(message, message_size, OIIO::geterror());
    const OIIO::ImageSpec& spec = input->spec();
    if (spec.nchannels < 1) return fail(message, message_size, "the image has no channels");
    const size_t pixels = static_cast<size_t>(spec.width) * static_cast<size_t>(spec.height);
    std::vector<float> all(pixels * static_cast<size_t>(spec.nchannels));
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()))
      return fail(message, message_size, input->geterror());
    auto* out = static_cast<float*>(std::malloc(3 * pixels * sizeof(float)));
    if (!out) return fail(message, message_size, "out of memory");
    // The first three channels, or grey (one or two channels) repeated into RGB.
    for (size_t p = 0; p < pixels; ++p)
      for (int c = 0; c < 3; ++c) out[3 * p + c] = all[p * spec.nchannels + (spec.nchannels >= 3 ? c : 0)];
    *width = spec.width;
    *height = spec.height;
    *rgb = out;
    return 0;
  } catch (const std::exception& error) {
    return fail(message, message_size, error.what());
  }
}

extern "C" __attribute__((visibility("default"))) void safegi_free_image_v1(float* rgb) { std::free(rgb); }
