// Vertex normals for shading (Shape::normals) from the ones a mesh file gives:
// pbrt's "N", a PLY's nx ny nz, an OBJ's vn, a JSON "normals" list.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::render {

// Each given normal (any length, one per position) made unit length. Files
// carry zero normals (a scanner's isolated or degenerate vertices) where
// pbrt-v3 would shade with NaNs: such a normal becomes the area-weighted mean
// of its triangles' winding normals (+z for a vertex no triangle uses, which
// nothing reads), so a mesh shades smoothly wherever its file says how.
std::vector<normal<Object>> unit_vertex_normals(std::span<const glm::dvec3> given, const std::vector<PointObject>& positions,
                                                const std::vector<uint32_t>& indices);

}  // namespace safegi::render
