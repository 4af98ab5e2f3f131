#include "safegi/cpu_renderer/precision.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace safegi::render {

namespace {

struct Box {
  double lo[3] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                  std::numeric_limits<double>::infinity()};
  double hi[3] = {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                  -std::numeric_limits<double>::infinity()};
  void add(const glm::dvec3& v) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], double(v[a]));
      hi[a] = std::max(hi[a], double(v[a]));
    }
  }
  bool empty() const { return lo[0] > hi[0]; }
  double diagonal() const {
    return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                     (hi[2] - lo[2]) * (hi[2] - lo[2]));
  }
  double farthest() const {
    double m = 0;
    for (int a = 0; a < 3; ++a) m = std::max({m, std::fabs(lo[a]), std::fabs(hi[a])});
    return m;
  }
};

// In double, so that the size reported is the scene's, not its rounding.
Box world_box(const Shape& shape, const RenderFromObject& render_from_object) {
  const glm::dmat4 matrix(sg::raw(render_from_object).forward);
  auto to_world = [&](const glm::dvec3& p) { return glm::dvec3(matrix * glm::dvec4(p, 1.0)); };
  Box box;
  if (shape.type == Shape::Type::sphere) {
    // The sphere's axis-aligned extremes in object space: enough under the
    // similarity transforms spheres are allowed.
    const glm::dvec3 c(sg::raw(shape.center));
    const double r = sg::raw(shape.radius);
    for (int a = 0; a < 3; ++a)
      for (double s : {-r, r}) {
        glm::dvec3 p = c;
        p[a] += s;
        box.add(to_world(p));
      }
  } else {
    for (uint32_t index : shape.indices) box.add(to_world(glm::dvec3(sg::raw(shape.positions[index]))));
  }
  return box;
}

// The distance between adjacent values of Real near x.
double spacing_at(double x) {
  Real r = static_cast<Real>(x);
  return double(std::nextafter(r, std::numeric_limits<Real>::infinity())) - double(r);
}

std::string metres(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g m", v);
  return text;
}

}  // namespace

std::optional<PrecisionReport> check_precision(const Scene& scene) {
  PrecisionReport report;
  double worst_fraction = 0;
  for (size_t i = 0; i < scene.shapes.size(); ++i) {
    const Shape& shape = scene.shapes[i];
    bool unresolved = false;
    for (const std::optional<RenderFromObject>& pose : {std::optional(shape.render_from_object),
                                                     shape.render_from_object_at_close}) {
      if (!pose) continue;
      Box box = world_box(shape, *pose);
      double size = box.empty() ? 0 : box.diagonal();
      if (!(size > 0)) continue;  // a point: nothing to resolve (zero-area shapes are allowed, and invisible)
      double distance = box.farthest(), spacing = spacing_at(distance);
      double fraction = spacing / size;
      if (!(fraction > kUnresolvedFraction)) continue;
      unresolved = true;
      if (fraction > worst_fraction) {
        worst_fraction = fraction;
        report.worst_shape = static_cast<int>(i);
        report.worst_size_m = size;
        report.worst_distance_m = distance;
        report.worst_spacing_m = spacing;
      }
    }
    report.unresolved_shapes += unresolved;
  }
  if (report.unresolved_shapes == 0) return std::nullopt;
  return report;
}

std::string describe(const PrecisionReport& report, const Scene& scene) {
  const bool is_float = sizeof(Real) == sizeof(float);
  const Shape& shape = scene.shapes.at(static_cast<size_t>(report.worst_shape));
  std::string name = "shapes[" + std::to_string(report.worst_shape) + "]";
  if (!shape.name.empty()) name += " \"" + shape.name + "\"";
  char percent[32];
  std::snprintf(percent, sizeof percent, "%.3g %%", 100 * report.worst_spacing_m / report.worst_size_m);
  std::string text = "warning: ";
  text += report.unresolved_shapes == 1 ? std::string("a shape is")
                                        : std::to_string(report.unresolved_shapes) + " shapes are";
  text += std::string(" too small for ") + kRealName + " where " + (report.unresolved_shapes == 1 ? "it stands" : "they stand") +
          ": " + name + " is " + metres(report.worst_size_m) + " across and " + metres(report.worst_distance_m) +
          " from the origin, where " + kRealName + " values are " + metres(report.worst_spacing_m) + " apart (" + percent +
          " of its size); expect a wrong image\n";
  text += std::string("help: ") + (is_float ? "render it in double (safegi-render-double), or " : "") +
          "move the scene towards the origin\n";
  return text;
}

}  // namespace safegi::render
