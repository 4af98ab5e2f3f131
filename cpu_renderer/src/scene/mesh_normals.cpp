#include "scene/mesh_normals.hpp"

#include <cmath>

#include <glm/geometric.hpp>

namespace safegi::render {

std::vector<normal<Object>> unit_vertex_normals(std::span<const glm::dvec3> given, const std::vector<PointObject>& positions,
                                                const std::vector<uint32_t>& indices) {
  auto usable = [](const glm::dvec3& n) {
    const double length = glm::length(n);
    return std::isfinite(length) && length > 1e-30;
  };
  std::vector<glm::dvec3> sum(given.begin(), given.end());
  std::vector<bool> fill(sum.size(), false);
  bool any = false;
  for (size_t i = 0; i < sum.size(); ++i) {
    if (usable(sum[i])) continue;
    fill[i] = any = true;
    sum[i] = glm::dvec3(0.0);
  }
  if (any) {
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
      const glm::dvec3 a(sg::raw(positions[indices[t]])), b(sg::raw(positions[indices[t + 1]])), c(sg::raw(positions[indices[t + 2]]));
      const glm::dvec3 area_normal = glm::cross(b - a, c - a);  // twice the area, along the winding normal
      for (size_t k = 0; k < 3; ++k)
        if (indices[t + k] < fill.size() && fill[indices[t + k]]) sum[indices[t + k]] += area_normal;
    }
  }
  std::vector<normal<Object>> out;
  out.reserve(sum.size());
  for (const glm::dvec3& n : sum) {
    const glm::dvec3 unit = usable(n) ? glm::normalize(n) : glm::dvec3(0, 0, 1);
    out.push_back(sg::from_raw<normal<Object>>(sg::vec3_rep(static_cast<Real>(unit.x), static_cast<Real>(unit.y), static_cast<Real>(unit.z))));
  }
  return out;
}

}  // namespace safegi::render
