// The interface of the image reader module (image_reader_module.cpp), which
// brings OpenImageIO into a program only when it reads an image.
#pragma once

#include <cstddef>

namespace safegi::render {
inline constexpr const char* kImageReaderModule = "libsafegi_image_reader.so";
}

extern "C" {
// Reads `path` as floats (see read_image in image_io.hpp): on success returns
// 0 and `*rgb` holds width·height·3 values, to be given back to
// safegi_free_image_v1; otherwise returns 1 with the reason in `message`.
int safegi_read_image_v1(const char* path, int* width, int* height, float** rgb, char* message,
                         std::size_t message_size);
void safegi_free_image_v1(float* rgb);
}
