// An emissive mesh as both renderers sample it: its triangles in one space
// with their cumulative area, a triangle chosen in proportion to area, and a
// uniform point on it. Public so that the GL preview places its light samples
// exactly where the CPU renderer's Lights would (one implementation, not two).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::render {

template <class Space>
struct EmitterTriangle {
  point<Space> p0;
  vector<Space> e1, e2;
  Real area_cdf;  // cumulative area within its emitter, 1 at its last triangle
};

// Appends the triangles of mesh `shape`, each vertex through `place` (object
// space → Space), to `triangles`; returns their total area. The new entries'
// area_cdf run up to 1 (an emitter of zero area is the caller's to skip).
template <class Space, class Place>
quantity<dim::area> append_emitter_triangles(const Shape& shape, const Place& place,
                                             std::vector<EmitterTriangle<Space>>& triangles) {
  const size_t first = triangles.size();
  quantity<dim::area> area = sg::zero;
  for (size_t i = 0; i + 2 < shape.indices.size(); i += 3) {
    point<Space> a = place(shape.positions[shape.indices[i]]);
    point<Space> b = place(shape.positions[shape.indices[i + 1]]);
    point<Space> c = place(shape.positions[shape.indices[i + 2]]);
    area += Real(0.5) * sg::length(sg::cross(b - a, c - a));
    triangles.push_back({a, b - a, c - a, sg::raw(area)});
  }
  for (size_t t = first; t < triangles.size(); ++t) triangles[t].area_cdf /= sg::raw(area);
  return area;
}

// The triangle of [first, last) that u in [0, 1) falls on by cumulative area.
template <class Space>
const EmitterTriangle<Space>* choose_emitter_triangle(const EmitterTriangle<Space>* first,
                                                      const EmitterTriangle<Space>* last, Real u) {
  const EmitterTriangle<Space>* found =
      std::upper_bound(first, last, u, [](Real v, const EmitterTriangle<Space>& t) { return v < t.area_cdf; });
  return found == last ? last - 1 : found;
}

// Barycentric weights of e1 and e2 for a point uniform over a triangle
// (the square root warps (u1, u2) so that equal areas get equal measure).
struct TriangleWeights {
  Real along_e1, along_e2;
};
inline TriangleWeights uniform_triangle_weights(Real u1, Real u2) {
  Real root = std::sqrt(u1);
  return {1 - root, u2 * root};
}

}  // namespace safegi::render
