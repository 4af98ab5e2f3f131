#include "textures/surface_texture.hpp"

#include <array>
#include <cmath>
#include <optional>

#include "safegi/cpu_renderer/sampling.hpp"

namespace safegi::render {

namespace {

// pbrt's default when a mesh has no texture coordinates: (0,0), (1,0), (1,1).
constexpr TexCoord kDefaultUv[3] = {{0, 0}, {1, 0}, {1, 1}};

TexCoord vertex_uv(const Shape& shape, size_t corner) {
  return shape.uvs.empty() ? kDefaultUv[corner % 3] : shape.uvs[shape.indices[corner]];
}

// A triangle's corners where `placed` puts its shape; `first` is its first index.
std::array<PointWorld, 3> placed_corners(const Shape& shape, const RenderFromObject& placed, size_t first) {
  return {placed(shape.positions[shape.indices[first]]), placed(shape.positions[shape.indices[first + 1]]),
          placed(shape.positions[shape.indices[first + 2]])};
}

// pbrt's sphere: u = φ/2π about object-space z, v = 1 − θ/π (0 at −z), of a
// point `offset` from the centre.
TexCoord sphere_uv(vector<Object> offset) {
  direction<Object> d = sg::normalize(offset);
  Real phi = std::atan2(d.y(), d.x());
  if (phi < 0) phi += 2 * kPi;
  return {phi / (2 * kPi), 1 - std::acos(std::clamp(d.z(), Real(-1), Real(1))) / kPi};
}

// The barycentric weights of `position` on the triangle with corners `p`;
// nothing for a degenerate triangle.
std::optional<std::array<Real, 3>> barycentrics(const std::array<PointWorld, 3>& p, PointWorld position) {
  VectorWorld e1 = p[1] - p[0], e2 = p[2] - p[0], d = position - p[0];
  quantity<dim::area> d11 = sg::dot(e1, e1), d12 = sg::dot(e1, e2), d22 = sg::dot(e2, e2);
  quantity<dim::area> d1 = sg::dot(d, e1), d2 = sg::dot(d, e2);
  auto determinant = d11 * d22 - d12 * d12;
  if (!(determinant > sg::zero)) return std::nullopt;
  const Real b1 = (d22 * d1 - d12 * d2) / determinant, b2 = (d11 * d2 - d12 * d1) / determinant;
  return std::array<Real, 3>{1 - b1 - b2, b1, b2};
}

// The (u, v) at `position` on the triangle with corners `p`, by its barycentric weights.
TexCoord triangle_uv(const Shape& shape, size_t first, const std::array<PointWorld, 3>& p, PointWorld position) {
  const std::optional<std::array<Real, 3>> b = barycentrics(p, position);
  if (!b) return vertex_uv(shape, first);
  TexCoord t0 = vertex_uv(shape, first), t1 = vertex_uv(shape, first + 1), t2 = vertex_uv(shape, first + 2);
  return {(*b)[0] * t0.u + (*b)[1] * t1.u + (*b)[2] * t2.u, (*b)[0] * t0.v + (*b)[1] * t1.v + (*b)[2] * t2.v};
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
    auto [a, b, c] = placed_corners(shape, render_from_object, i);
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

RenderFromObject SurfaceTextures::render_from_object(const Shape& shape, uint32_t index, Time time) const {
  return motions_[index] ? motions_[index]->render_from_object(time) : shape.render_from_object;
}

TexCoord SurfaceTextures::uv(const SurfaceHit& hit, Time time) const {
  const Shape& shape = scene_.shapes[hit.shape];
  const RenderFromObject placed = render_from_object(shape, hit.shape, time);
  if (shape.type == Shape::Type::sphere) return sphere_uv(sg::inverse(placed)(hit.position) - shape.center);
  // Where the triangle is at `time`.
  const size_t first = 3 * static_cast<size_t>(hit.face);
  return triangle_uv(shape, first, placed_corners(shape, placed, first), hit.position);
}

Reflectance SurfaceTextures::diffuse(const Material& material, const SurfaceHit& hit, const ConeFootprint& footprint,
                                     Time time) const {
  const TexturedReflectance* diffuse = diffuse_of(material);
  return diffuse ? reflectance_at(*diffuse, hit, footprint, time) : Reflectance{};
}

Reflectance SurfaceTextures::reflectance_at(const TexturedReflectance& reflectance, const SurfaceHit& hit,
                                            const ConeFootprint& footprint, Time time) const {
  const TexturedReflectance* diffuse = &reflectance;
  if (!diffuse->textured()) return diffuse->value;
  // Isotropic lookups take the ellipse's long axis.
  const bool filtered = footprint.width > sg::zero;
  Length width = sg::zero;
  SurfaceAxes axes{};
  if (filtered) {
    axes = cone_axes_on_surface(hit.normal, footprint);
    width = std::max(kernel::length(axes[0]), kernel::length(axes[1])) * units::meter;
  }
  if (diffuse->pattern >= 0) {
    const Pattern& pattern = scene_.patterns[diffuse->pattern].pattern;
    PatternLookup lookup{.position = hit.position, .width = width};
    if (reads_uv(pattern)) {
      if (filtered) {
        const Derivatives at = derivatives(hit, time);
        lookup.u = at.uv.u;
        lookup.v = at.uv.v;
        const Real isotropic = sg::raw(width * uv_per_length_[hit.shape]);  // where (u, v) has no frame
        std::tie(lookup.u_footprint, lookup.v_footprint) =
            cone_uv_extent(at.dp_du, at.dp_dv, axes).value_or(std::pair{isotropic, isotropic});
      } else {
        const TexCoord at = uv(hit, time);
        lookup.u = at.u;
        lookup.v = at.v;
      }
    }
    return diffuse->value * evaluate(pattern, lookup);
  }
  const ImageTexture& texture = scene_.textures[diffuse->texture];
  if (texture.filter != TextureFilter::bilinear && filtered && texture.mapping.kind == Mapping2D::Kind::uv) {
    const Derivatives at = derivatives(hit, time);
    const TextureCoordinates st = texture.mapping.at(at.uv.u, at.uv.v, hit.position);
    if (const std::optional<std::array<TexCoord, 2>> in_uv = cone_uv_axes(at.dp_du, at.dp_dv, axes)) {
      auto in_st = [&](TexCoord axis) { return StExtent{axis.u * texture.mapping.u_scale, axis.v * texture.mapping.v_scale}; };
      const StExtent a = in_st((*in_uv)[0]), b = in_st((*in_uv)[1]);
      if (texture.filter == TextureFilter::ewa)
        return diffuse->value * texture.mipmap->ewa(st.s, st.t, a, b, texture.max_anisotropy);
      // pbrt-v3's trilinear: twice the largest step in s or in t.
      const Real reach = std::max({std::abs(a.s), std::abs(a.t), std::abs(b.s), std::abs(b.t)});
      return diffuse->value * texture.mipmap->trilinear(st.s, st.t, 2 * reach);
    }
  }
  TexCoord at = uv(hit, time);
  const TextureCoordinates st = texture.mapping.at(at.u, at.v, hit.position);
  const Real texels = width * uv_per_length_[hit.shape] * texture.mapping.uv_scale();  // where (u, v) has no frame
  if (texture.filter == TextureFilter::bilinear || !(texels > 0)) return diffuse->value * texture.mipmap->bilinear(0, st.s, st.t);
  return diffuse->value * texture.mipmap->trilinear(st.s, st.t, texels);
}

namespace {

// pbrt-v3's CoordinateSystem: two unit vectors perpendicular to n and to each other.
std::pair<DirectionWorld, DirectionWorld> perpendiculars(DirectionWorld n) {
  DirectionWorld first = std::abs(n.x()) > std::abs(n.y())
                             ? sg::normalize(vector<World, dim::dimensionless>(-n.z(), 0, n.x()))
                             : sg::normalize(vector<World, dim::dimensionless>(0, n.z(), -n.y()));
  return {first, sg::normalize(sg::cross(n, first))};
}

// The luminance of a float image texture at (u, v) and `position`, as pbrt-v3
// converts an image's RGB to a float texture (RGBSpectrum::y).
Real luminance_at(const ImageTexture& texture, TexCoord at, PointWorld position) {
  const TextureCoordinates st = texture.mapping.at(at.u, at.v, position);
  glm::vec3 rgb = sg::raw(texture.mipmap->bilinear(0, st.s, st.t));
  return 0.212671f * rgb.x + 0.715160f * rgb.y + 0.072169f * rgb.z;
}

}  // namespace

SurfaceAxes cone_axes_on_surface(NormalWorld normal, const ConeFootprint& footprint) {
  // Plain numbers in metres: the uv solve mixes the axes' lengths with dp/du's.
  const Real3 n = to_kernel(sg::to_direction(normal)), direction = to_kernel(footprint.direction);
  const Real cosine = kernel::dot(n, direction);
  const Real tilt = std::max(std::abs(cosine), Real(1e-3));
  const Real width = sg::raw(footprint.width);
  const Real3 step_x = to_kernel(footprint.step_x), step_y = to_kernel(footprint.step_y);
  if (kernel::dot(step_x, step_x) > 0 || kernel::dot(step_y, step_y) > 0) {
    // Each step slid along the ray onto the plane (pbrt-v3's offset rays met with the tangent plane).
    const Real signed_tilt = cosine < 0 ? -tilt : tilt;
    auto onto_plane = [&](Real3 step) { return (step - direction * (kernel::dot(n, step) / signed_tilt)) * width; };
    return {onto_plane(step_x), onto_plane(step_y)};
  }
  Real3 along = direction - n * cosine;  // the slope's direction on the surface
  if (!(kernel::length(along) > Real(1e-6))) along = to_kernel(perpendiculars(sg::to_direction(normal)).first);
  along = kernel::normalize(along);
  const Real3 across = kernel::cross(n, along);
  return {along * (width / tilt), across * width};
}

std::optional<std::array<TexCoord, 2>> cone_uv_axes(VectorWorld dp_du, VectorWorld dp_dv, const SurfaceAxes& axes) {
  const Real3 pu = to_kernel(dp_du), pv = to_kernel(dp_dv);
  const Real uu = kernel::dot(pu, pu), uv = kernel::dot(pu, pv), vv = kernel::dot(pv, pv);
  const Real determinant = uu * vv - uv * uv;
  if (!(determinant > 1e-12f * uu * vv)) return std::nullopt;
  std::array<TexCoord, 2> in_uv;
  for (int i = 0; i < 2; ++i) {
    const Real along_u = kernel::dot(pu, axes[i]), along_v = kernel::dot(pv, axes[i]);
    in_uv[i] = {(vv * along_u - uv * along_v) / determinant, (uu * along_v - uv * along_u) / determinant};
  }
  return in_uv;
}

std::optional<std::pair<Real, Real>> cone_uv_extent(VectorWorld dp_du, VectorWorld dp_dv, const SurfaceAxes& axes) {
  const std::optional<std::array<TexCoord, 2>> in_uv = cone_uv_axes(dp_du, dp_dv, axes);
  if (!in_uv) return std::nullopt;
  return std::pair{std::max(std::abs((*in_uv)[0].u), std::abs((*in_uv)[1].u)),
                   std::max(std::abs((*in_uv)[0].v), std::abs((*in_uv)[1].v))};
}

SurfaceTextures::Derivatives SurfaceTextures::derivatives(const SurfaceHit& hit, Time time) const {
  const Shape& shape = scene_.shapes[hit.shape];
  const RenderFromObject placed = render_from_object(shape, hit.shape, time);
  Derivatives d;
  if (shape.type == Shape::Type::sphere) {
    // pbrt-v3's Sphere::Intersect for the whole sphere (φmax = 2π, θ from π to 0);
    // its normal is the radius direction, so dn/du = dp/du / r.
    vector<Object> offset = sg::inverse(placed)(hit.position) - shape.center;
    d.uv = sphere_uv(offset);
    const Length x = offset.x(), y = offset.y(), z = offset.z(), r = sg::length(offset);
    const Length ring = sg::sqrt(x * x + y * y);
    const Real cos_phi = ring > sg::zero ? x / ring : Real(1), sin_phi = ring > sg::zero ? y / ring : Real(0);
    const Real sin_theta = ring / r;
    d.dp_du = placed(vector<Object>(-2 * kPi * y, 2 * kPi * x, sg::zero));
    d.dp_dv = placed(vector<Object>(-kPi * z * cos_phi, -kPi * z * sin_phi, kPi * r * sin_theta));
    const Length placed_r = placed_radius(placed, r);
    d.dn_du = d.dp_du / placed_r;
    d.dn_dv = d.dp_dv / placed_r;
    return d;
  }
  // pbrt-v3's Triangle::Intersect: dp/du and dp/dv from the corners' (u, v),
  // or any two perpendicular directions where those are degenerate. Flat
  // triangles: the normal does not change.
  const size_t first = 3 * static_cast<size_t>(hit.face);
  const std::array<PointWorld, 3> corners = placed_corners(shape, placed, first);
  const auto& [p0, p1, p2] = corners;
  d.uv = triangle_uv(shape, first, corners, hit.position);
  TexCoord t0 = vertex_uv(shape, first), t1 = vertex_uv(shape, first + 1), t2 = vertex_uv(shape, first + 2);
  const Real du02 = t0.u - t2.u, dv02 = t0.v - t2.v, du12 = t1.u - t2.u, dv12 = t1.v - t2.v;
  const VectorWorld dp02 = p0 - p2, dp12 = p1 - p2;
  const Real determinant = du02 * dv12 - dv02 * du12;
  bool degenerate = std::abs(determinant) < 1e-8f;
  if (!degenerate) {
    d.dp_du = (dv12 * dp02 - dv02 * dp12) / determinant;
    d.dp_dv = (du02 * dp12 - du12 * dp02) / determinant;
    degenerate = !(sg::length_squared(sg::cross(d.dp_du, d.dp_dv)) > sg::zero);
  }
  if (degenerate) {
    auto [along_u, along_v] = perpendiculars(sg::to_direction(hit.normal));
    const Length metre = Real(1) * units::meter;
    d.dp_du = along_u * metre;
    d.dp_dv = along_v * metre;
  }
  return d;
}

NormalWorld SurfaceTextures::bumped_normal(const BumpMap& bump, const SurfaceHit& hit, Time time) const {
  const Derivatives d = derivatives(hit, time);
  // The displacement where the surface's (u, v) is `uv` and its point `p`
  // (pbrt-v3 shifts both: a solid pattern reads the point).
  auto displacement_at = [&](TexCoord uv, PointWorld p) -> Length {
    if (bump.texture >= 0) return bump.scale * luminance_at(scene_.textures[bump.texture], uv, p);
    const PatternLookup lookup{.u = uv.u, .v = uv.v, .position = p};
    return bump.scale * evaluate_number(scene_.patterns[bump.pattern].pattern, lookup);
  };
  // pbrt-v3's step for rays without differentials; its camera rays step by
  // their footprint over sqrt(spp), which also tends to the texel's own slope.
  // The steps actually taken (u + 0.0005 rounds): dividing by them keeps the
  // slope's rounding error that of the texture's values.
  constexpr Real step = 0.0005f;
  const Real u_next = d.uv.u + step, v_next = d.uv.v + step;
  const Real u_step = u_next - d.uv.u, v_step = v_next - d.uv.v;
  const Length displacement = displacement_at(d.uv, hit.position);
  const Length along_u = displacement_at({u_next, d.uv.v}, hit.position + d.dp_du * u_step);
  const Length along_v = displacement_at({d.uv.u, v_next}, hit.position + d.dp_dv * v_step);
  const VectorWorld dp_du = d.dp_du + hit.normal * ((along_u - displacement) / u_step) + d.dn_du * displacement;
  const VectorWorld dp_dv = d.dp_dv + hit.normal * ((along_v - displacement) / v_step) + d.dn_dv * displacement;
  const auto perpendicular = sg::cross(dp_du, dp_dv);
  if (!(sg::length_squared(perpendicular) > sg::zero)) return hit.normal;
  return sg::face_forward(sg::to_normal(sg::normalize(perpendicular)), sg::to_direction(hit.normal));
}

NormalWorld SurfaceTextures::interpolated_normal(const SurfaceHit& hit, Time time) const {
  const Shape& shape = scene_.shapes[hit.shape];
  if (shape.type != Shape::Type::mesh || shape.normals.empty()) return hit.normal;
  const RenderFromObject placed = render_from_object(shape, hit.shape, time);
  const size_t first = 3 * static_cast<size_t>(hit.face);
  const std::optional<std::array<Real, 3>> b = barycentrics(placed_corners(shape, placed, first), hit.position);
  if (!b) return hit.normal;
  const vector<Object, dim::dimensionless> sum = (*b)[0] * shape.normals[shape.indices[first]] +
                                                 (*b)[1] * shape.normals[shape.indices[first + 1]] +
                                                 (*b)[2] * shape.normals[shape.indices[first + 2]];
  if (!(sg::length_squared(sum) > Real(1e-12))) return hit.normal;
  // Normals transform by the placement's inverse transpose (an animated pose may scale).
  const NormalWorld n = placed(sg::to_normal(sg::normalize(sum)));
  return sg::face_forward(n, sg::to_direction(hit.normal));
}

}  // namespace safegi::render
