// The SPIR-V options' spellings and the .spv bytes: no glslang here, so the
// plain safeglslc (which never links glslang) parses -V/-G flags too.
#include "safegi/compiler/spirv.hpp"

namespace safegi {

bool apply_target_env(std::string_view name, SpirvOptions& options) {
  for (int minor = 0; minor < 4; ++minor) {
    if (name == "vulkan1." + std::to_string(minor)) {
      options.client = SpirvClient::vulkan;
      options.vulkan_minor = minor;
      return true;
    }
  }
  if (name == "opengl") {
    options.client = SpirvClient::opengl;
    return true;
  }
  for (int minor = 0; minor < 7; ++minor) {
    if (name == "spirv1." + std::to_string(minor)) {
      options.spirv_minor = minor;
      return true;
    }
  }
  return false;
}

std::string spirv_bytes(const std::vector<std::uint32_t>& words) {
  std::string bytes;
  bytes.reserve(words.size() * 4);
  for (std::uint32_t word : words)
    for (int shift = 0; shift < 32; shift += 8) bytes += static_cast<char>((word >> shift) & 0xff);
  return bytes;
}

}  // namespace safegi
