// Rendering kernels written once against the portable API. The zero-overhead test
// compiles this file checked and unchecked (-O2) and requires the assembly of every
// kernel to be identical: the types cost nothing at run time.
#include <safegi/typed.hpp>

namespace sg = safegi;
using sg::spaces::object;
using sg::spaces::shading;
using sg::spaces::world;

extern "C" {

// Direct lighting of a point from a point light: Li f cos / pdf.
sg::spectrum<sg::dim::radiance> shade_point_light(sg::point<world> p, sg::normal<world> n,
                                                  sg::spectrum<sg::dim::brdf> f, sg::point<world> light,
                                                  sg::spectrum<sg::dim::intensity> intensity) {
  const sg::vector<world> to_light = light - p;
  const sg::quantity<sg::dim::area> r2 = sg::length_squared(to_light);
  const sg::direction<world> wi = sg::normalize(to_light);
  const sg::quantity<sg::dim::proj> cosine = sg::dot(n, wi);
  if (cosine <= sg::zero) return {};
  const sg::spectrum<sg::dim::radiance> Li = intensity / r2 / sg::units::proj;
  const sg::quantity<sg::dim::pdf_solid_angle> pdf = 1.0f / (1.0f * sg::units::steradian);
  return Li * f * cosine / pdf;
}

// A normal and a direction taken to world space, then dotted.
sg::quantity<sg::dim::proj> transform_and_dot(const sg::map<object, world>& worldFromObject, sg::normal<object> n,
                                              sg::direction<object> w) {
  return sg::dot(worldFromObject(n), worldFromObject(w));
}

// A point through two composed maps.
sg::point<world> transform_point(const sg::map<object, world>& worldFromObject,
                                 const sg::map<world, world>& motion, sg::point<object> p) {
  return (motion * worldFromObject)(p);
}

// The point along a ray at distance t, given in millimetres.
sg::point<world> ray_point(const sg::ray<world>& r, float t_millimetres) {
  return r(t_millimetres * sg::units::millimetre);
}

// A shading-frame round trip with the local cosine.
sg::quantity<sg::dim::proj> local_cosine(sg::normal<world> n, sg::direction<world> w) {
  const sg::frame<world> frame = sg::frame<world>::from_normal(n);
  return sg::cos_theta(frame.to_local(w));
}

// Scalar radiometry: a Lambertian emitter's radiance from its power and area.
sg::quantity<sg::dim::radiance> emitted_radiance(sg::quantity<sg::dim::power> phi, sg::quantity<sg::dim::area> a) {
  return phi / (a * sg::pi * sg::units::steradian * sg::units::proj);
}

// Angles and units: the elevation of w in degrees.
float elevation_degrees(sg::direction<world> w) {
  return sg::in(sg::asin(w.z()), sg::units::degree);
}

// A light's facing factor toward a lens, through the opt-in orientation words: the
// direction handed to the light is oriented (lens to light), which costs nothing.
float oriented_light_facing(sg::point<world> lens_position, sg::point<world> light, sg::normal<world> n) {
  // shaded(p) in place: a named shaded_point local costs GCC 12 a larger stack frame
  // (orientation.hpp says so), the orientation itself nothing.
  const sg::oriented<sg::away, sg::direction<world>> lens_to_light = sg::normalize(light - sg::shaded(lens_position));
  return -sg::raw(sg::dot(n, lens_to_light));
}

// A tangent frame from dp/du and the azimuth of a direction in it.
float tangent_azimuth(sg::normal<world> n, sg::vector<world> dpdu, sg::direction<world> w) {
  const auto tbn = sg::frame<world, sg::spaces::tangent>::from_tangent(dpdu, n);
  const sg::direction<sg::spaces::tangent> local = tbn.to_local(w);
  return sg::cos_phi(local) * sg::sin_theta(local);
}

// A ray's reach clipped by a hit distance, from std::numeric_limits of a quantity.
sg::quantity<sg::dim::length> clipped_reach(sg::quantity<sg::dim::length> hit, bool found) {
  return found ? hit : std::numeric_limits<sg::quantity<sg::dim::length>>::infinity();
}

}  // extern "C"
