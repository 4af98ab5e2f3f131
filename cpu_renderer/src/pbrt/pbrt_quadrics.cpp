// pbrt-v3's quadrics (src/shapes/disk.cpp, cylinder.cpp, cone.cpp,
// paraboloid.cpp, hyperboloid.cpp, and sphere.cpp's partial spheres) as
// triangle meshes in object space. Each is pbrt's parametric surface p(u, v)
// over u = φ/φmax, v in [0, 1], sampled on a grid: the texture coordinates are
// pbrt's (u, v), and every triangle is wound so that its winding normal is
// pbrt's surface normal ∂p/∂u × ∂p/∂v, the side an area light emits on (the
// importer's placement then flips it as pbrt-v3 does, for ReverseOrientation
// and for transforms that swap handedness).
//
// Accuracy: 256 segments per full turn keep a circle's polygon within
// 1 − sin(2π/256)/(2π/256) ≈ 1.0e-4 of its area; surfaces curved along v get
// 64 rings, flat or straight ones (disk, cylinder, cone) one.
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "pbrt/pbrt_importer.hpp"

namespace safegi::render::pbrt {

namespace {

constexpr int kSegmentsPerTurn = 256;
constexpr int kCurvedRings = 64;

// pbrt-v3's phimax: degrees in (0, 360], as radians.
double phi_max(ParamSet& params, SourceRange at) {
  double degrees = params.one_float("phimax", 360);
  if (!(degrees > 0 && degrees <= 360))
    fail(at, "\"float phimax\" of " + params.context() + " must lie in (0, 360], found " + std::to_string(degrees));
  return degrees * std::numbers::pi / 180;
}

// The grid of p(u, v): `segments` × `rings` quads, two triangles each;
// triangles of zero area (at an apex or a disk's centre) are left out.
void tessellate(const std::function<glm::dvec3(double, double)>& surface, double phi_max, int rings,
                ShapeSource& source) {
  const int segments = std::max(3, static_cast<int>(std::ceil(kSegmentsPerTurn * phi_max / (2 * std::numbers::pi))));
  for (int j = 0; j <= rings; ++j)
    for (int i = 0; i <= segments; ++i) {
      double u = static_cast<double>(i) / segments, v = static_cast<double>(j) / rings;
      source.positions.push_back(surface(u, v));
      source.uvs.push_back({static_cast<Real>(u), static_cast<Real>(v)});
    }
  triangulate_grid(segments + 1, rings + 1, source);
}

glm::dvec3 around_z(double radius, double phi, double z) { return {radius * std::cos(phi), radius * std::sin(phi), z}; }

double positive(ParamSet& params, const char* name, double fallback, SourceRange at) {
  double value = params.one_float(name, fallback);
  if (!(value > 0 && std::isfinite(value)))
    fail(at, "\"float " + std::string(name) + "\" of " + params.context() + " must be positive");
  return value;
}

}  // namespace

void triangulate_grid(int columns, int rows, ShapeSource& source) {
  auto vertex = [&](int i, int j) { return static_cast<uint32_t>(j * columns + i); };
  auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
    glm::dvec3 n = glm::cross(source.positions[b] - source.positions[a], source.positions[c] - source.positions[a]);
    if (!(glm::length(n) > 0)) return;
    source.indices.insert(source.indices.end(), {a, b, c});
  };
  for (int j = 0; j + 1 < rows; ++j)
    for (int i = 0; i + 1 < columns; ++i) {
      // (u, v) → (u + du, v) → (u + du, v + dv): counter-clockwise about ∂p/∂u × ∂p/∂v.
      add(vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1));
      add(vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1));
    }
}

bool quadric_mesh(const std::string& type, ParamSet& params, SourceRange at, ShapeSource& source) {
  if (type == "disk") {
    double height = params.one_float("height", 0), radius = positive(params, "radius", 1, at);
    double inner = params.one_float("innerradius", 0), phi = phi_max(params, at);
    if (!(inner >= 0 && inner < radius))
      fail(at, "\"float innerradius\" of " + params.context() + " must lie in [0, radius)");
    tessellate([&](double u, double v) { return around_z(radius - v * (radius - inner), u * phi, height); }, phi, 1,
               source);
  } else if (type == "cylinder") {
    double radius = positive(params, "radius", 1, at);
    double z0 = params.one_float("zmin", -1), z1 = params.one_float("zmax", 1), phi = phi_max(params, at);
    double zmin = std::min(z0, z1), zmax = std::max(z0, z1);  // pbrt-v3 orders them
    tessellate([&](double u, double v) { return around_z(radius, u * phi, zmin + v * (zmax - zmin)); }, phi, 1, source);
  } else if (type == "cone") {
    double height = positive(params, "height", 1, at), radius = positive(params, "radius", 1, at);
    double phi = phi_max(params, at);
    tessellate([&](double u, double v) { return around_z(radius * (1 - v), u * phi, v * height); }, phi, 1, source);
  } else if (type == "paraboloid") {
    double radius = positive(params, "radius", 1, at);
    double z0 = params.one_float("zmin", 0), z1 = params.one_float("zmax", 1), phi = phi_max(params, at);
    double zmin = std::min(z0, z1), zmax = std::max(z0, z1);
    if (!(zmin >= 0 && zmax > 0)) fail(at, "a paraboloid's \"zmin\" and \"zmax\" must not be negative, nor both zero");
    tessellate(
        [&](double u, double v) {
          double z = zmin + v * (zmax - zmin);
          return around_z(radius * std::sqrt(z / zmax), u * phi, z);
        },
        phi, kCurvedRings, source);
  } else if (type == "hyperboloid") {
    // The line from p1 to p2 turned about z.
    std::optional<Triple> p1 = params.one_point("p1"), p2 = params.one_point("p2");
    glm::dvec3 a = p1 ? glm::dvec3((*p1)[0], (*p1)[1], (*p1)[2]) : glm::dvec3(0, 0, 0);
    glm::dvec3 b = p2 ? glm::dvec3((*p2)[0], (*p2)[1], (*p2)[2]) : glm::dvec3(1, 1, 1);
    double phi = phi_max(params, at);
    tessellate(
        [&](double u, double v) {
          glm::dvec3 p = (1 - v) * a + v * b;
          double c = std::cos(u * phi), s = std::sin(u * phi);
          return glm::dvec3(p.x * c - p.y * s, p.x * s + p.y * c, p.z);
        },
        phi, kCurvedRings, source);
  } else {
    return false;
  }
  if (source.indices.empty()) fail(at, params.context() + " has no area");
  return true;
}

bool sphere_mesh(double radius, bool even_if_whole, ParamSet& params, SourceRange at, ShapeSource& source) {
  double z0 = params.one_float("zmin", -radius), z1 = params.one_float("zmax", radius);
  double phi = phi_max(params, at);
  // pbrt-v3's clamping, and its v: 0 at zmin, 1 at zmax.
  double zmin = std::clamp(std::min(z0, z1), -radius, radius), zmax = std::clamp(std::max(z0, z1), -radius, radius);
  if (!even_if_whole && zmin == -radius && zmax == radius && phi == 2 * std::numbers::pi) return false;
  double theta_min = std::acos(std::clamp(zmin / radius, -1.0, 1.0)), theta_max = std::acos(std::clamp(zmax / radius, -1.0, 1.0));
  tessellate(
      [&](double u, double v) {
        double theta = theta_min + v * (theta_max - theta_min);
        return around_z(radius * std::sin(theta), u * phi, radius * std::cos(theta));
      },
      phi, kCurvedRings, source);
  if (source.indices.empty()) fail(at, params.context() + " has no area");
  return true;
}

}  // namespace safegi::render::pbrt
