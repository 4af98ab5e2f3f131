// Texture lookups at surface hits: a hit's (u, v) on its shape, and how large
// the pixel it stands for is on the texture (for the MIP level).
//
// The footprint is a ray cone (Akenine-Möller et al. 2019, "Texture Level of
// Detail Strategies for Real-Time Ray Tracing"): a camera ray spreads by the
// angle one pixel subtends, so after a distance t (summed over the specular
// bounces before the hit) it covers t · spread (narrowed by 1/√spp, as pbrt-v3
// narrows its ray differentials), stretched by 1/|cos θ| on a
// tilted surface; a shape's (u, v) area per world area turns that into
// texture units. A pattern in (u, v) (a checkerboard) is filtered over the
// cone's ellipse instead, its extent in u and in v each (pbrt-v3's
// max(|ds/dx|, |ds/dy|) and its t twin): a check seen at a grazing angle is
// blurred along the slope, not across it. After a diffuse bounce the
// footprint is taken as zero (the finest level, bilinear), as pbrt-v3 does
// for rays without differentials.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "accel/geometry.hpp"
#include "safegi/cpu_renderer/rigid_motion.hpp"
#include "safegi/cpu_renderer/scene.hpp"

namespace safegi::render {

// Where a ray cone meets a surface: its width across (zero: the finest level,
// no filtering) and the ray's direction, along whose slope it stretches.
struct ConeFootprint {
  Length width = sg::zero;
  DirectionWorld direction{0, 0, 1};
  // The image's x and y pixel steps seen along the ray, each perpendicular to
  // `direction` and as long as that step is over `width` (1 at a perspective
  // image's centre, about ½ at the corner of a 90° one): pbrt-v3's ray
  // differentials, whose ellipse and box extents follow them. Zero: the
  // circle's own axes, along the slope and across it.
  ConeStep step_x{}, step_y{};
};

// Two semi-axes of a footprint's ellipse on a surface, in metres.
using SurfaceAxes = std::array<Real3, 2>;

// The footprint's semi-axes on a surface of normal `normal` (`width` across
// the ray's slope, width/|cos θ| along it; or its steps', carried along the
// ray onto the surface's plane).
SurfaceAxes cone_axes_on_surface(NormalWorld normal, const ConeFootprint& footprint);

// Those axes written in `dp_du` and `dp_dv` by least squares, as (du, dv)
// each. Nothing where dp/du and dp/dv are parallel.
std::optional<std::array<TexCoord, 2>> cone_uv_axes(VectorWorld dp_du, VectorWorld dp_dv, const SurfaceAxes& axes);
// The largest |du| and the largest |dv| of them (pbrt-v3's
// max(|du/dx|, |du/dy|) and its v twin).
std::optional<std::pair<Real, Real>> cone_uv_extent(VectorWorld dp_du, VectorWorld dp_dv, const SurfaceAxes& axes);

class SurfaceTextures {
 public:
  explicit SurfaceTextures(const Scene& scene);

  bool any() const { return scene_.textured(); }

  // The hit's texture coordinates on its shape at `time`.
  TexCoord uv(const SurfaceHit& hit, Time time) const;

  // The diffuse reflectance of `material` at `hit`, its texture (if any)
  // filtered over `footprint`.
  Reflectance diffuse(const Material& material, const SurfaceHit& hit, const ConeFootprint& footprint, Time time) const;
  // Any textured reflectance at `hit`, filtered alike.
  Reflectance reflectance_at(const TexturedReflectance& reflectance, const SurfaceHit& hit,
                             const ConeFootprint& footprint, Time time) const;

  // The normal of the surface `bump` displaces (pbrt-v3's Material::Bump), on
  // the side of the hit's geometric normal; that normal where it is undefined.
  NormalWorld bumped_normal(const BumpMap& bump, const SurfaceHit& hit, Time time) const;

  // The shape's vertex normals interpolated at the hit (pbrt-v3's shading
  // normal), on the side of the hit's geometric normal; that normal where the
  // shape has none or they cancel.
  NormalWorld interpolated_normal(const SurfaceHit& hit, Time time) const;

 private:
  // How the surface and its normal change along u and along v at a hit
  // (pbrt-v3's dpdu, dpdv, dndu, dndv), with the hit's (u, v).
  struct Derivatives {
    TexCoord uv;
    VectorWorld dp_du, dp_dv;
    vector<World, dim::dimensionless> dn_du, dn_dv;
  };
  Derivatives derivatives(const SurfaceHit& hit, Time time) const;
  RenderFromObject render_from_object(const Shape& shape, uint32_t index, Time time) const;

  const Scene& scene_;
  // Per shape, sqrt((u, v) area / world area): texture units per length.
  std::vector<quantity<dim::inverse<dim::length>>> uv_per_length_;
  std::vector<std::optional<RigidMotion>> motions_;
};

}  // namespace safegi::render
