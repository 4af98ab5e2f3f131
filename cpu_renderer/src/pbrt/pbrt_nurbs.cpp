// pbrt-v3's "nurbs" shape (src/shapes/nurbs.cpp) as the triangle mesh pbrt-v3
// itself renders: the surface evaluated on a 30 × 30 grid over [u0, u1] ×
// [v0, v1] (its fixed dicing rate), two triangles per grid cell wound as pbrt's
// (so the winding normal is ∂p/∂u × ∂p/∂v, the side an area light emits on),
// texture coordinates (u, v), and pbrt-v3's vertex normals ∂p/∂u × ∂p/∂v,
// which shade. Control points are "point P" (nu × nv, u
// fastest) or homogeneous "float Pw" (x·w, y·w, z·w, w each), evaluated by
// de Boor's algorithm in homogeneous coordinates as pbrt-v3 does.
#include <algorithm>
#include <cmath>
#include <functional>
#include <span>
#include <vector>

#include "pbrt/pbrt_importer.hpp"

namespace safegi::render::pbrt {

namespace {

constexpr int kDice = 30;  // pbrt-v3's diceu = dicev = 30

// The knot interval [knot[k], knot[k + 1]] that holds t, for control point count np.
int knot_offset(std::span<const double> knot, int order, int np, double t) {
  int offset = order - 1;
  while (offset < np - 1 && t > knot[offset + 1]) ++offset;
  return offset;
}

// A B-spline curve of `order` over homogeneous control points cp[i * stride], at
// t; with `derivative`, also d(xyz / w)/dt there (pbrt-v3's NURBSEvaluate).
glm::dvec4 evaluate_curve(int order, std::span<const double> knot, const glm::dvec4* cp, int np, int stride, double t,
                          glm::dvec3* derivative = nullptr) {
  const int offset = knot_offset(knot, order, np, t);
  const int first = offset - order + 1;
  std::vector<glm::dvec4> work(order);
  for (int i = 0; i < order; ++i) work[i] = cp[(first + i) * stride];
  const double* k = knot.data() + offset;
  for (int i = 0; i < order - 2; ++i)
    for (int j = 0; j < order - 1 - i; ++j) {
      const double span = k[1 + j] - k[j + 2 - order + i];
      const double alpha = span > 0 ? (k[1 + j] - t) / span : 0.0;
      work[j] = work[j] * alpha + work[j + 1] * (1 - alpha);
    }
  const double span = k[1] - k[0];
  const double alpha = span > 0 ? (k[1] - t) / span : 0.0;
  const glm::dvec4 value = work[0] * alpha + work[1] * (1 - alpha);
  if (derivative) {
    const glm::dvec4 delta = span > 0 ? (work[1] - work[0]) * ((order - 1) / span) : glm::dvec4(0.0);
    *derivative = glm::dvec3(delta) / value.w - glm::dvec3(value) * (delta.w / (value.w * value.w));
  }
  return value;
}

struct SurfacePoint {
  glm::dvec3 position, dp_du, dp_dv;
};

SurfacePoint evaluate_surface(int u_order, std::span<const double> u_knot, int nu, double u, int v_order,
                              std::span<const double> v_knot, int nv, double v, const std::vector<glm::dvec4>& cp) {
  SurfacePoint out;
  // The v-curves through the u-interval's control columns, then the u-curve through them; for ∂p/∂v the other way round.
  const int u_first = knot_offset(u_knot, u_order, nu, u) - u_order + 1;
  const int v_first = knot_offset(v_knot, v_order, nv, v) - v_order + 1;
  std::vector<glm::dvec4> iso(std::max(u_order, v_order));
  for (int i = 0; i < u_order; ++i) iso[i] = evaluate_curve(v_order, v_knot, &cp[u_first + i], nv, nu, v);
  const glm::dvec4 p = evaluate_curve(u_order, u_knot, iso.data() - u_first, nu, 1, u, &out.dp_du);
  for (int i = 0; i < v_order; ++i)
    iso[i] = evaluate_curve(u_order, u_knot, &cp[static_cast<size_t>(v_first + i) * nu], nu, 1, u);
  (void)evaluate_curve(v_order, v_knot, iso.data() - v_first, nv, 1, v, &out.dp_dv);
  out.position = glm::dvec3(p) / p.w;
  return out;
}

// pbrt-v3's vertex normal ∂p/∂u × ∂p/∂v; where a derivative vanishes (a
// pole), the normal a step inside the parameter range, its limit there.
glm::dvec3 surface_normal(const SurfacePoint& at, const std::function<SurfacePoint(double, double)>& nudged) {
  const glm::dvec3 n = glm::cross(at.dp_du, at.dp_dv);
  const double size = glm::length(at.dp_du) * glm::length(at.dp_dv);
  if (glm::length(n) > 1e-9 * size && size > 0) return n;
  const SurfacePoint inside = nudged(1e-4, 1e-4);
  return glm::cross(inside.dp_du, inside.dp_dv);
}

struct Direction {
  const char* n;
  const char* order;
  const char* knots;
  const char* t0;
  const char* t1;
};

struct Knots {
  int count = 0;
  int order = 0;
  std::vector<double> knots;
  double t0 = 0, t1 = 0;
};

Knots read_knots(ParamSet& params, SourceRange at, const Direction& d) {
  Knots k;
  k.count = params.one_int(d.n, -1, -1, 1 << 16);
  k.order = params.one_int(d.order, -1, -1, 64);
  if (k.count < 0 || k.order < 0)
    fail(at, params.context() + " needs \"integer " + d.n + "\" and \"integer " + d.order + "\"");
  if (k.order < 2 || k.count < k.order)
    fail(at, params.context() + ": \"" + d.order + "\" " + std::to_string(k.order) + " needs 2 ≤ order ≤ \"" + d.n +
                 "\" (" + std::to_string(k.count) + ")");
  k.knots = params.floats(d.knots);
  if (k.knots.size() != static_cast<size_t>(k.count + k.order))
    fail(at, params.context() + ": \"float " + d.knots + "\" needs " + d.n + " + " + d.order + " = " +
                 std::to_string(k.count + k.order) + " knots, found " + std::to_string(k.knots.size()));
  for (size_t i = 0; i + 1 < k.knots.size(); ++i)
    if (!(k.knots[i] <= k.knots[i + 1]) || !std::isfinite(k.knots[i + 1]))
      fail(at, params.context() + ": \"float " + d.knots + "\" must not decrease (knot " + std::to_string(i + 1) + ")");
  k.t0 = params.one_float(d.t0, k.knots[k.order - 1]);
  k.t1 = params.one_float(d.t1, k.knots[k.count]);
  if (!(k.t0 >= k.knots[k.order - 1] && k.t1 <= k.knots[k.count] && k.t0 < k.t1))
    fail(at, params.context() + ": \"" + d.t0 + "\" and \"" + d.t1 + "\" must lie in the knots' range [" +
                 std::to_string(k.knots[k.order - 1]) + ", " + std::to_string(k.knots[k.count]) + "], in order");
  return k;
}

}  // namespace

bool nurbs_mesh(const std::string& type, ParamSet& params, SourceRange at, ShapeSource& source) {
  if (type != "nurbs") return false;
  const Knots u = read_knots(params, at, {"nu", "uorder", "uknots", "u0", "u1"});
  const Knots v = read_knots(params, at, {"nv", "vorder", "vknots", "v0", "v1"});
  const size_t points = static_cast<size_t>(u.count) * static_cast<size_t>(v.count);
  std::vector<glm::dvec4> cp;
  if (const Param* p = params.find("P", {ParamType::point3})) {
    if (p->numbers.size() != 3 * points)
      fail(p->values, "\"point P\" of " + params.context() + " needs nu × nv = " + std::to_string(points) +
                          " points, found " + std::to_string(p->numbers.size()) + " numbers");
    for (size_t i = 0; i < points; ++i) cp.emplace_back(p->numbers[3 * i], p->numbers[3 * i + 1], p->numbers[3 * i + 2], 1.0);
  } else if (const Param* pw = params.find("Pw", {ParamType::floating})) {
    if (pw->numbers.size() != 4 * points)
      fail(pw->values, "\"float Pw\" of " + params.context() + " needs 4 numbers (x·w, y·w, z·w, w) for each of nu × nv = " +
                           std::to_string(points) + " points, found " + std::to_string(pw->numbers.size()));
    for (size_t i = 0; i < points; ++i) {
      const double* n = &pw->numbers[4 * i];
      if (!(n[3] > 0)) fail(pw->values, "\"float Pw\" of " + params.context() + ": weight " + std::to_string(i) + " is not positive");
      cp.emplace_back(n[0], n[1], n[2], n[3]);
    }
  } else {
    fail(at, params.context() + " needs \"point P\" or \"float Pw\" (its control points)");
  }
  for (int j = 0; j < kDice; ++j)
    for (int i = 0; i < kDice; ++i) {
      const double s = u.t0 + (u.t1 - u.t0) * i / (kDice - 1), t = v.t0 + (v.t1 - v.t0) * j / (kDice - 1);
      auto at = [&](double ds, double dt) {  // ds, dt: steps towards the middle, as fractions of the range
        const double su = s + (i < kDice / 2 ? ds : -ds) * (u.t1 - u.t0), tv = t + (j < kDice / 2 ? dt : -dt) * (v.t1 - v.t0);
        return evaluate_surface(u.order, u.knots, u.count, su, v.order, v.knots, v.count, tv, cp);
      };
      const SurfacePoint point = at(0, 0);
      source.positions.push_back(point.position);
      source.normals.push_back(surface_normal(point, at));
      source.uvs.push_back({static_cast<Real>(s), static_cast<Real>(t)});
    }
  triangulate_grid(kDice, kDice, source);
  if (source.indices.empty()) fail(at, params.context() + " has no area");
  return true;
}

}  // namespace safegi::render::pbrt
