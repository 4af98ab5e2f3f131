#include "surface_texture.hpp"

#include <cmath>

#include "safegi/cpu_renderer/sampling.hpp"

namespace safegi::render {

namespace {

// pbrt's default when a mesh has no texture coordinates: (0,0), (1,0), (1,1).
constexpr TexCoord kDefaultUv[3] = {{0, 0}, {1, 0}, {1, 1}};

TexCoord vertex_uv(const Shape& shape, size_t corner) {
  return shape.uvs.empty() ? kDefaultUv[corner % 3] : shape.uvs[shape.indices[corner]];
}

// How much texture a length of the surface spans: the square root of the
// shape's total (u, v) area (a number) over its total world area.
quantity<dim::inverse<dim::length>> uv_per_length(const Shape& shape) {
  const RenderFromObject& render_from_object = shape.render_from_object;
  if (shape.type == Shape::Type::sphere) {
    Length radius = placed_radius(render_from_object, shape.radius);
    return 1 / sg::sqrt(4 * kPi * radius * radius);  // (u, v) ∈ [0, 1)² covers the sphere once
  }
  Real uv_area = 0;
  quantity<dim::area> world_area = sg::zero;
  for (size_t i = 0; i + 2 < shape.indices.size(); i += 3) {
    PointWorld a = render_from_object(shape.positions[shape.indices[i]]), b = render_from_object(shape.positions[shape.indices[i + 1]]),
               c = render_from_object(shape.positions[shape.indices[i + 2]]);
    world_area += 0.5f * sg::length(sg::cross(b - a, c - a));
    TexCoord ta = vertex_uv(shape, i), tb = vertex_uv(shape, i + 1), tc = vertex_uv(shape, i + 2);
    uv_area += std::abs((tb.u - ta.u) * (tc.v - ta.v) - (tc.u - ta.u) * (tb.v - ta.v)) / 2;
  }
  if (!(world_area > sg::zero)) return sg::zero;
  return sg::sqrt(uv_area / world_area);
}

}  // namespace

SurfaceTextures::SurfaceTextures(const Scene& scene) : scene_(scene) {
  if (!scene.textured()) return;
  for (const Shape& shape : scene.shapes) {
    uv_per_length_.push_back(uv_per_length(shape));
    motions_.push_back(motion_of(shape, scene.camera));
  }
}

TexCoord SurfaceTextures::uv(const SurfaceHit& hit, Time time) const {
  const Shape& shape = scene_.shapes[hit.shape];
  if (shape.type == Shape::Type::sphere) {
    // pbrt's sphere: u = φ/2π about object-space z, v = 1 − θ/π (0 at −z).
    RenderFromObject render_from_object = motions_[hit.shape] ? motions_[hit.shape]->render_from_object(time) : shape.render_from_object;
    vector<Object> offset = sg::inverse(render_from_object)(hit.position) - shape.center;
    direction<Object> d = sg::normalize(offset);
    Real phi = std::atan2(d.y(), d.x());
    if (phi < 0) phi += 2 * kPi;
    return {phi / (2 * kPi), 1 - std::acos(std::clamp(d.z(), Real(-1), Real(1))) / kPi};
  }
  // The hit's barycentric weights on its triangle, where the triangle is at `time`.
  const size_t first = 3 * static_cast<size_t>(hit.face);
  RenderFromObject render_from_object = motions_[hit.shape] ? motions_[hit.shape]->render_from_object(time) : shape.render_from_object;
  PointWorld a = render_from_object(shape.positions[shape.indices[first]]), b = render_from_object(shape.positions[shape.indices[first + 1]]),
             c = render_from_object(shape.positions[shape.indices[first + 2]]);
  VectorWorld e1 = b - a, e2 = c - a, d = hit.position - a;
  quantity<dim::area> d11 = sg::dot(e1, e1), d12 = sg::dot(e1, e2), d22 = sg::dot(e2, e2);
  quantity<dim::area> d1 = sg::dot(d, e1), d2 = sg::dot(d, e2);
  auto determinant = d11 * d22 - d12 * d12;
  if (!(determinant > sg::zero)) return vertex_uv(shape, first);
  const Real b1 = (d22 * d1 - d12 * d2) / determinant, b2 = (d11 * d2 - d12 * d1) / determinant;
  const Real b0 = 1 - b1 - b2;
  TexCoord t0 = vertex_uv(shape, first), t1 = vertex_uv(shape, first + 1), t2 = vertex_uv(shape, first + 2);
  return {b0 * t0.u + b1 * t1.u + b2 * t2.u, b0 * t0.v + b1 * t1.v + b2 * t2.v};
}

Reflectance SurfaceTextures::diffuse(const Material& material, const SurfaceHit& hit, Length width, Time time) const {
  const TexturedReflectance* diffuse = diffuse_of(material);
  if (!diffuse) return Reflectance{};
  if (!diffuse->textured()) return diffuse->value;
  if (diffuse->pattern >= 0) {
    const Pattern& pattern = scene_.patterns[diffuse->pattern].pattern;
    PatternLookup lookup{.position = hit.position, .width = width};
    if (reads_uv(pattern)) {
      TexCoord at = uv(hit, time);
      lookup.u = at.u;
      lookup.v = at.v;
      lookup.uv_footprint = width * uv_per_length_[hit.shape];
    }
    return diffuse->value * evaluate(pattern, lookup);
  }
  const ImageTexture& texture = scene_.textures[diffuse->texture];
  TexCoord at = uv(hit, time);
  const UvMapping& m = texture.mapping;
  const Real s = at.u * m.u_scale + m.u_offset, t = at.v * m.v_scale + m.v_offset;
  if (texture.filter == TextureFilter::bilinear || !(width > sg::zero))
    return diffuse->value * texture.mipmap->bilinear(0, s, t);
  const Real footprint = width * uv_per_length_[hit.shape] * std::max(std::abs(m.u_scale), std::abs(m.v_scale));
  return diffuse->value * texture.mipmap->trilinear(s, t, footprint);
}

}  // namespace safegi::render
