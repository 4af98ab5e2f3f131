// Image files. EXR and PNG are written here with OpenEXR and libpng; images
// are read through OpenImageIO, in a module (image_reader_module.cpp) loaded on
// the first read. Linked into the programs, OpenImageIO's ~270 libraries cost
// every run ~125 MiB of memory and ~0.25 s at start, also one that reads no
// image (docs/benchmarks.md, the renderer at scale).
#include "safegi/cpu_renderer/image_io.hpp"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <dlfcn.h>
#include <png.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdint>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "film/image_reader_module.hpp"

namespace safegi::render {

float linear_to_srgb(float linear) {
  float v = std::clamp(std::isnan(linear) ? 0.0f : linear, 0.0f, 1.0f);
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

void write_exr(const std::filesystem::path& file, const Image& image, std::string_view description) {
  try {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    if (!description.empty()) header.insert("ImageDescription", Imf::StringAttribute(std::string(description)));
    Imf::FrameBuffer frame;
    const char* names[] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
      header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
      frame.insert(names[c], Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(&image.rgb[c])),
                                        3 * sizeof(float), 3 * sizeof(float) * static_cast<size_t>(image.width)));
    }
    Imf::OutputFile output(file.c_str(), header);
    output.setFrameBuffer(frame);
    output.writePixels(image.height);
  } catch (const std::exception& error) {
    throw ImageError(file.string() + ": cannot write image: " + error.what());
  }
}

namespace {

// libpng reports errors by longjmp; this keeps the message for the exception
// thrown once control is back in C++.
struct PngErrors {
  std::jmp_buf jump;
  char message[256] = "";
};

void on_png_error(png_structp png, png_const_charp message) {
  auto* errors = static_cast<PngErrors*>(png_get_error_ptr(png));
  std::snprintf(errors->message, sizeof errors->message, "%s", message);
  std::longjmp(errors->jump, 1);
}

void on_png_warning(png_structp, png_const_charp) {}

}  // namespace

void write_png(const std::filesystem::path& file, const Image& image, std::string_view description) {
  std::vector<uint8_t> bytes(image.rgb.size());
  for (size_t i = 0; i < bytes.size(); ++i)
    bytes[i] = static_cast<uint8_t>(std::lround(linear_to_srgb(image.rgb[i]) * 255.0f));
  std::vector<png_bytep> rows(static_cast<size_t>(image.height));
  for (size_t y = 0; y < rows.size(); ++y) rows[y] = bytes.data() + 3 * static_cast<size_t>(image.width) * y;
  const std::string text(description);
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> out(std::fopen(file.c_str(), "wb"), std::fclose);
  if (!out) throw ImageError(file.string() + ": cannot write image: " + std::strerror(errno));
  PngErrors errors;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &errors, on_png_error, on_png_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  // Everything that outlives a longjmp is made above; nothing below holds a destructor.
  if (!png || !info || setjmp(errors.jump)) {
    png_destroy_write_struct(&png, &info);
    throw ImageError(file.string() + ": cannot write image: " + (errors.message[0] ? errors.message : "out of memory"));
  }
  png_init_io(png, out.get());
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_text note{};
  if (!text.empty()) {
    note.compression = PNG_TEXT_COMPRESSION_NONE;
    note.key = const_cast<char*>("Description");
    note.text = const_cast<char*>(text.c_str());
    png_set_text(png, info, &note, 1);
  }
  png_set_rows(png, info, rows.data());
  png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
  png_destroy_write_struct(&png, &info);
}

namespace {

// The reader module, loaded once: beside the program (the build tree), or in
// the installed library folder.
struct ReaderModule {
  decltype(&safegi_read_image_v1) read = nullptr;
  decltype(&safegi_free_image_v1) release = nullptr;
  std::string error;  // why it could not be loaded
};

ReaderModule load_reader_module() {
  std::error_code ignored;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", ignored);
  const std::filesystem::path folder = program.parent_path();
  ReaderModule module;
  for (const std::filesystem::path& candidate :
       {folder / kImageReaderModule, folder / ".." / SAFEGI_IMAGE_READER_INSTALL_DIR / kImageReaderModule}) {
    void* handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      module.error += (module.error.empty() ? "" : "; ") + std::string(dlerror());
      continue;
    }
    module.read = reinterpret_cast<decltype(module.read)>(dlsym(handle, "safegi_read_image_v1"));
    module.release = reinterpret_cast<decltype(module.release)>(dlsym(handle, "safegi_free_image_v1"));
    if (module.read && module.release) return module;
    module.error += (module.error.empty() ? "" : "; ") + candidate.string() + " has no safegi_read_image_v1";
  }
  module.read = nullptr;
  return module;
}

}  // namespace

Image read_image(const std::filesystem::path& file) {
  static const ReaderModule module = load_reader_module();
  if (!module.read)
    throw ImageError(file.string() + ": cannot read image: OpenImageIO's reader " + kImageReaderModule +
                     " could not be loaded (" + module.error + ")");
  Image image;
  float* rgb = nullptr;
  char message[512] = "";
  if (module.read(file.c_str(), &image.width, &image.height, &rgb, message, sizeof message) != 0)
    throw ImageError(file.string() + ": cannot read image: " + message);
  std::unique_ptr<float, decltype(module.release)> owned(rgb, module.release);
  image.rgb.assign(rgb, rgb + 3 * static_cast<size_t>(image.width) * static_cast<size_t>(image.height));
  return image;
}

}  // namespace safegi::render
