// pbrt-v3's "heightfield" shape (src/shapes/heightfield.cpp) as the triangle
// mesh pbrt-v3 itself makes of it: nu × nv heights "float Pz" (x fastest) over
// the unit square, vertex (i, j) at (i / (nu − 1), j / (nv − 1), Pz) with those
// two numbers as its texture coordinates, two triangles per cell split along
// the cell's (i, j)–(i + 1, j + 1) diagonal, and no vertex normals (pbrt-v3
// shades it flat).
#include <string>

#include "pbrt/pbrt_importer.hpp"

namespace safegi::render::pbrt {

bool heightfield_mesh(const std::string& type, ParamSet& params, SourceRange at, ShapeSource& source) {
  if (type != "heightfield") return false;
  const int columns = params.one_int("nu", -1, -1, 1 << 20);
  const int rows = params.one_int("nv", -1, -1, 1 << 20);
  if (columns < 2 || rows < 2)
    fail(at, params.context() + " needs \"integer nu\" and \"integer nv\", each at least 2 (its grid of heights)");
  const Param* heights = params.find("Pz", {ParamType::floating});
  if (!heights) fail(at, params.context() + " needs \"float Pz\" (nu × nv heights)");
  const size_t points = static_cast<size_t>(columns) * static_cast<size_t>(rows);
  if (heights->numbers.size() != points)
    fail(heights->values, "\"float Pz\" of " + params.context() + " needs nu × nv = " + std::to_string(points) +
                              " heights, found " + std::to_string(heights->numbers.size()));
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const double x = static_cast<double>(i) / (columns - 1), y = static_cast<double>(j) / (rows - 1);
      source.positions.emplace_back(x, y, heights->numbers[static_cast<size_t>(j) * columns + i]);
      source.uvs.push_back({static_cast<Real>(x), static_cast<Real>(y)});
    }
  triangulate_grid(columns, rows, source);
  if (source.indices.empty()) fail(at, params.context() + " has no area");
  return true;
}

}  // namespace safegi::render::pbrt
