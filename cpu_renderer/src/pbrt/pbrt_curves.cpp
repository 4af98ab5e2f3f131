// pbrt-v3's "curve" shape (src/shapes/curve.cpp) as a triangle mesh in object
// space: its control points read as pbrt-v3 reads them (Bézier or B-spline,
// degree 2 or 3, every segment made a cubic Bézier as CreateCurveShape makes
// it), its width lerped from width0 to width1 along the whole curve, and
// - "cylinder" and "flat": a tube of that diameter around the spine (8 sides,
//   outward vertex normals). pbrt-v3 intersects both as a ribbon facing the
//   ray (a cylinder's normal is turned to fake a round one), so a tube has
//   their silhouette from every side; a flat curve's shading differs (pbrt-v3
//   lights it as a strip facing the viewer), which the importer warns about;
// - "ribbon": a strip across the spine, perpendicular to its normals ("N", one
//   per segment end, interpolated as pbrt-v3 does, its width scaled as pbrt-v3 scales it).
// Each segment is cut into 16 steps along u; pbrt-v3's "splitdepth" (its
// refinement of the exact curve) is read and unused.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "pbrt/pbrt_importer.hpp"
#include "safegi/cpu_renderer/memory_estimate.hpp"

namespace safegi::render::pbrt {

namespace {

constexpr int kStepsPerSegment = 16;
constexpr int kTubeSides = 8;

using Cubic = std::array<glm::dvec3, 4>;

glm::dvec3 lerp(double t, glm::dvec3 a, glm::dvec3 b) { return (1 - t) * a + t * b; }

glm::dvec3 bezier(const Cubic& cp, double u) {
  const glm::dvec3 a = lerp(u, cp[0], cp[1]), b = lerp(u, cp[1], cp[2]), c = lerp(u, cp[2], cp[3]);
  return lerp(u, lerp(u, a, b), lerp(u, b, c));
}

glm::dvec3 bezier_tangent(const Cubic& cp, double u) {
  const glm::dvec3 a = lerp(u, cp[1] - cp[0], cp[2] - cp[1]), b = lerp(u, cp[2] - cp[1], cp[3] - cp[2]);
  return 3.0 * lerp(u, a, b);
}

// The segments as cubic Béziers, as pbrt-v3's CreateCurveShape converts them.
std::vector<Cubic> segments(const std::vector<glm::dvec3>& cp, int degree, bool bspline, const ParamSet& params,
                            SourceRange at) {
  const int n = static_cast<int>(cp.size());
  std::vector<Cubic> out;
  if (!bspline) {
    if (n < degree + 1 || (n - 1 - degree) % degree != 0)
      fail(at, params.context() + ": a degree " + std::to_string(degree) + " Bézier curve needs " +
                   std::to_string(degree + 1) + " + k·" + std::to_string(degree) + " control points, found " +
                   std::to_string(n));
    for (int i = 0; i + degree < n; i += degree) {
      const glm::dvec3* p = &cp[i];
      if (degree == 3) out.push_back({p[0], p[1], p[2], p[3]});
      else out.push_back({p[0], lerp(2.0 / 3, p[0], p[1]), lerp(1.0 / 3, p[1], p[2]), p[2]});  // elevated to cubic
    }
    return out;
  }
  if (n < degree + 1)
    fail(at, params.context() + ": a degree " + std::to_string(degree) + " B-spline curve needs at least " +
                 std::to_string(degree + 1) + " control points, found " + std::to_string(n));
  for (int i = 0; i + degree < n; ++i) {
    const glm::dvec3* p = &cp[i];
    if (degree == 3) {
      const glm::dvec3 p122 = lerp(2.0 / 3, p[0], p[1]), p223 = lerp(1.0 / 3, p[1], p[2]);
      const glm::dvec3 p233 = lerp(2.0 / 3, p[1], p[2]), p334 = lerp(1.0 / 3, p[2], p[3]);
      out.push_back({lerp(0.5, p122, p223), p223, p233, lerp(0.5, p233, p334)});
    } else {
      const glm::dvec3 p11 = lerp(0.5, p[0], p[1]), p22 = lerp(0.5, p[1], p[2]);
      out.push_back({p11, lerp(2.0 / 3, p11, p[1]), lerp(1.0 / 3, p[1], p22), p22});
    }
  }
  return out;
}

// A ribbon's normal at u between its segment's end normals, as pbrt-v3's
// Curve computes it: spherically interpolated over the angle between them with
// the cosine clamped to [0, 1], and not normalised — normals more than 90°
// apart give a shorter one (down to 0 between opposite normals), and pbrt-v3
// scales the ribbon's width by its length.
glm::dvec3 ribbon_normal(double u, glm::dvec3 n0, glm::dvec3 n1) {
  const double angle = std::acos(std::clamp(glm::dot(n0, n1), 0.0, 1.0));
  if (angle == 0) return n0;
  return (std::sin((1 - u) * angle) * n0 + std::sin(u * angle) * n1) / std::sin(angle);
}

glm::dvec3 unit(glm::dvec3 v, glm::dvec3 fallback) {
  const double length = glm::length(v);
  return length > 0 && std::isfinite(length) ? v / length : fallback;
}

// Any unit vector perpendicular to unit `t`.
glm::dvec3 perpendicular(glm::dvec3 t) {
  const glm::dvec3 axis = std::abs(t.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  return glm::normalize(glm::cross(t, axis));
}

// Refuses the triangles `adding` once the scene's curves would pass what fits
// in the memory a render may take (the render's own check, done before
// anything is made: the render's bytes per triangle and the import's copy).
void check_curve_budget(uint64_t& made, uint64_t adding, const ParamSet& params, SourceRange at) {
  const std::optional<AvailableMemory> available = available_memory();
  const uint64_t bytes_each = render_bytes_per_triangle() + 3 * sizeof(glm::dvec3) + sizeof(TexCoord);
  made += adding;
  if (!available || made <= available->bytes / 100 * kUsableMemoryPercent / bytes_each) return;
  fail(at, params.context() + ": the scene's curves make " + std::to_string(made) + " triangles so far, more than fit in " +
               std::to_string(kUsableMemoryPercent) + " % of the " + format_bytes(available->bytes) + " available (" +
               available->source + ") at about " + format_bytes(bytes_each) + " each",
       "each curve segment is " + std::to_string(kStepsPerSegment * kTubeSides * 2) + " triangles here (a ribbon's " +
           std::to_string(kStepsPerSegment * 2) + ")");
}

}  // namespace

bool curve_mesh(const std::string& type, ParamSet& params, SourceRange at, ShapeSource& source, uint64_t& curve_triangles) {
  if (type != "curve") return false;
  const Param* p = params.find("P", {ParamType::point3});
  if (!p || p->numbers.empty() || p->numbers.size() % 3 != 0)
    fail(at, params.context() + " needs \"point P\": its control points, x y z each");
  std::vector<glm::dvec3> cp;
  for (size_t i = 0; i < p->numbers.size(); i += 3) cp.emplace_back(p->numbers[i], p->numbers[i + 1], p->numbers[i + 2]);
  const int degree = params.one_int("degree", 3, 2, 3);
  const std::string basis = params.one_string("basis", "bezier");
  if (basis != "bezier" && basis != "bspline")
    params.fail_at(*params.find("basis", {ParamType::string}), "unknown basis \"" + basis + "\"",
                   "pbrt-v3 has \"bezier\" and \"bspline\"");
  const std::vector<Cubic> curve = segments(cp, degree, basis == "bspline", params, at);
  const double width = params.one_float("width", 1);
  const double width0 = params.one_float("width0", width), width1 = params.one_float("width1", width);
  if (!(width0 >= 0 && width1 >= 0 && std::isfinite(width0) && std::isfinite(width1) && width0 + width1 > 0))
    fail(at, params.context() + ": its widths must be finite, not negative, and not both 0");
  const std::string kind = params.one_string("type", "flat");
  if (kind != "flat" && kind != "ribbon" && kind != "cylinder")
    params.fail_at(*params.find("type", {ParamType::string}), "unknown curve type \"" + kind + "\"",
                   "pbrt-v3 has \"flat\", \"ribbon\" and \"cylinder\"");
  params.one_int("splitdepth", 3, 0, 64);
  const int count = static_cast<int>(curve.size());
  std::vector<glm::dvec3> normals;
  if (kind == "ribbon") {
    const Param* n = params.find("N", {ParamType::normal});
    if (!n || n->numbers.size() != 3 * static_cast<size_t>(count + 1))
      fail(n ? n->values : at, params.context() + ": a ribbon needs \"normal N\", one per segment end: " +
                                   std::to_string(count + 1) + " normals");
    for (size_t i = 0; i < n->numbers.size(); i += 3)
      normals.push_back(unit({n->numbers[i], n->numbers[i + 1], n->numbers[i + 2]}, {0, 0, 1}));
  }

  const int per_segment = kStepsPerSegment * (kind == "ribbon" ? 2 : 2 * kTubeSides);
  check_curve_budget(curve_triangles, static_cast<uint64_t>(count) * per_segment, params, at);
  const int rows = count * kStepsPerSegment + 1;
  const int columns = kind == "ribbon" ? 2 : kTubeSides + 1;
  glm::dvec3 across = perpendicular(unit(bezier_tangent(curve[0], 0), unit(curve[0][3] - curve[0][0], {0, 0, 1})));
  for (int row = 0; row < rows; ++row) {
    const int segment = std::min(row / kStepsPerSegment, count - 1);
    const double u = static_cast<double>(row - segment * kStepsPerSegment) / kStepsPerSegment;
    const double along = static_cast<double>(row) / (rows - 1);  // u over the whole curve
    const Cubic& c = curve[segment];
    const glm::dvec3 spine = bezier(c, u);
    const glm::dvec3 tangent = unit(bezier_tangent(c, u), unit(c[3] - c[0], {0, 0, 1}));
    const double radius = 0.5 * ((1 - along) * width0 + along * width1);
    if (kind == "ribbon") {
      const glm::dvec3 normal = ribbon_normal(u, normals[segment], normals[segment + 1]);
      const glm::dvec3 side = unit(glm::cross(normal, tangent), perpendicular(tangent)) * glm::length(normal);
      for (int s = 0; s < 2; ++s) {
        source.positions.push_back(spine + (s == 0 ? radius : -radius) * side);
        source.normals.push_back(unit(normal, unit(normals[segment] + normals[segment + 1], normals[segment])));
        source.uvs.push_back({static_cast<Real>(along), static_cast<Real>(s)});
      }
      continue;
    }
    // A frame carried along the spine (the previous row's projected onto this one's plane): no twist.
    across = unit(across - glm::dot(across, tangent) * tangent, perpendicular(tangent));
    const glm::dvec3 other = glm::cross(tangent, across);
    for (int s = 0; s <= kTubeSides; ++s) {
      const double theta = 2 * std::numbers::pi * (s % kTubeSides) / kTubeSides;
      const glm::dvec3 outward = std::cos(theta) * across + std::sin(theta) * other;
      source.positions.push_back(spine + radius * outward);
      source.normals.push_back(outward);
      source.uvs.push_back({static_cast<Real>(along), static_cast<Real>(static_cast<double>(s) / kTubeSides)});
    }
  }
  // Columns across, rows along: around the tube ∂p/∂θ × ∂p/∂u points out.
  triangulate_grid(columns, rows, source);
  if (kind == "ribbon") {
    // The ribbon's winding to its normals' side.
    for (size_t t = 0; t + 2 < source.indices.size(); t += 3) {
      const uint32_t* v = &source.indices[t];
      const glm::dvec3 n = glm::cross(source.positions[v[1]] - source.positions[v[0]], source.positions[v[2]] - source.positions[v[0]]);
      if (glm::dot(n, source.normals[v[0]]) < 0) std::swap(source.indices[t + 1], source.indices[t + 2]);
    }
  }
  if (source.indices.empty()) fail(at, params.context() + " has no area");
  return true;
}

}  // namespace safegi::render::pbrt
