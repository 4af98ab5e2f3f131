// A small reader for PLY triangle meshes (ASCII and binary, either byte order):
// vertex x y z with optional nx ny nz and texture coordinates (u v, s t,
// texture_u texture_v or texture_s texture_t), faces as vertex-index lists (triangles,
// quads and larger convex polygons, fanned into triangles). Other elements and
// properties are skipped. Any malformed or truncated file is a PlyError naming
// the header line or the element where reading stopped; never a crash.
#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace safegi::render {

class PlyError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct PlyMesh {
  std::vector<std::array<float, 3>> positions;
  std::vector<std::array<float, 3>> normals;  // empty, or one per position
  std::vector<std::array<float, 2>> uvs;      // empty, or one per position
  std::vector<uint32_t> indices;              // three per triangle
};

// Parses the bytes of a PLY file; throws PlyError (message without file name).
PlyMesh parse_ply(std::string_view bytes);

}  // namespace safegi::render
