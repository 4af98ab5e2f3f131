// Coordinate spaces and the geometric kinds that live in them.
//
// A space is a tag type declared in one line:
//   struct world : safegi::space_tag<"world"> {};      or   SAFEGI_SPACE(world);
// point<S> (a position), vector<S, D = dim::length> (a displacement, or any vector with
// dimension D), direction<S> (unit length, dimensionless), normal<S> (unit length,
// transformed by the inverse transpose) and hpoint<S> (homogeneous, from projective maps).
//
// Affine rules: point - point = vector, point ± vector = point, point + point is an
// error; every binary operation needs both operands in one space.
//
// Result dimensions of products (documented in docs/typed/reference.md):
//   dot(vector<S,D>, vector<S,E>) = quantity<D·E>        e.g. vector·vector = area
//   dot(direction, direction)     = dimensionless        (a cosine between directions)
//   dot(normal, direction)        = quantity<dim::proj>  (the rendering equation's cosine)
//   dot(normal, normal)           = dimensionless
//   dot(direction|normal, vector<S,D>) = quantity<D>     (the component along the unit vector)
//   cross(vector<S,D>, vector<S,E>) = vector<S, D·E>;  cross(direction, direction) = vector<S, 1>
//   cross(vector<S,D>, direction or normal) = vector<S, D> (either order)
// Sums of unit vectors (direction or normal ± direction or normal) are vector<S, 1>;
// vector<S, D> ± a unit vector needs D dimensionless (as in the shader language).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "safegi/typed/quantity.hpp"
#include "safegi/typed/representation.hpp"

namespace safegi {

template <fixed_string Name>
struct space_tag {
  static constexpr auto name = Name;
};

template <class S>
concept space_type = requires {
  S::name;
  requires std::is_base_of_v<space_tag<S::name>, S>;
};

namespace space_detail {
struct frame_space_marker {};
struct tangent_frame_marker {};
}  // namespace space_detail

/// The local space of a frame built from a normal alone (frame<S, L>::from_normal): the
/// normal is +z, and x and y are some orthonormal pair around it: the azimuth is
/// arbitrary, so it is not the dp/du-aligned tangent frame a normal map or an
/// anisotropic BSDF needs. cos_theta and the other polar angles read it.
///   struct shading : safegi::normal_frame_tag<"shading"> {};   or   SAFEGI_NORMAL_FRAME_SPACE(shading);
template <fixed_string Name>
struct normal_frame_tag : space_tag<Name>, ::safegi::space_detail::frame_space_marker {};
/// The local space of a tangent frame (frame<S, L>::from_tangent(dpdu, n)): +z the
/// normal, +x along dp/du, +y along dp/dv's part orthogonal to both. Normal-map texels
/// and anisotropic roughness live here; from_normal refuses it.
///   struct tangent : safegi::tangent_frame_tag<"tangent"> {};  or   SAFEGI_TANGENT_FRAME_SPACE(tangent);
template <fixed_string Name>
struct tangent_frame_tag : space_tag<Name>, ::safegi::space_detail::frame_space_marker, ::safegi::space_detail::tangent_frame_marker {};

/// A frame's local space (either kind): the normal is +z.
template <class S>
inline constexpr bool is_frame_space = std::is_base_of_v<::safegi::space_detail::frame_space_marker, S>;
/// A tangent frame's local space: +x is dp/du.
template <class S>
inline constexpr bool is_tangent_frame_space = std::is_base_of_v<::safegi::space_detail::tangent_frame_marker, S>;

/// Spaces most renderers need; declare your own the same way.
namespace spaces {
struct world : space_tag<"world"> {};
struct object : space_tag<"object"> {};
struct camera : space_tag<"camera"> {};
struct light : space_tag<"light"> {};
/// The local shading frame built from the shading normal alone: the normal is +z, the
/// azimuth arbitrary (frame<S>::from_normal).
struct shading : normal_frame_tag<"shading"> {};
/// The local space of a tangent frame: +z the normal, +x along dp/du (frame::from_tangent).
struct tangent : tangent_frame_tag<"tangent"> {};
struct clip : space_tag<"clip"> {};
struct ndc : space_tag<"ndc"> {};
struct raster : space_tag<"raster"> {};
}  // namespace spaces

inline namespace SAFEGI_MODE_NAMESPACE {

/// The one space of the unchecked build.
struct any_space : space_tag<"unchecked"> {};

/// S in the checked build; every space collapses to any_space in the unchecked build.
template <class S>
using mode_space = std::conditional_t<is_checked, S, any_space>;

template <class S>
class basic_point;
template <class S, class D>
class basic_vector;
template <class S>
class basic_direction;
template <class S>
class basic_normal;
template <class S>
class basic_hpoint;

template <space_type S>
using point = basic_point<mode_space<S>>;
template <space_type S, dimension_type D = dim::length>
using vector = basic_vector<mode_space<S>, mode_dimension<D>>;
template <space_type S>
using direction = basic_direction<mode_space<S>>;
template <space_type S>
using normal = basic_normal<mode_space<S>>;
template <space_type S>
using hpoint = basic_hpoint<mode_space<S>>;

namespace detail {
/// The length dimension as the current mode sees it.
using length_dimension = mode_dimension<dim::length>;
template <class S>
using displacement = basic_vector<S, length_dimension>;

template <dimension_type D>
constexpr quantity<D> component(real value) {
  return make_quantity<mode_dimension<D>, real>(value);
}

#if SAFEGI_CHECK_UNIT_LENGTH
/// Not constexpr on purpose: reached during constant evaluation it makes the
/// initialiser a compile error; at run time it stops the program with the culprit.
[[noreturn]] inline void report_not_unit_length(const char* kind, const char* space, vec3_rep xyz) {
  std::fprintf(stderr,
               "safegi: %s<%s>(%g, %g, %g) is not unit length (length %g); build it with normalize(vector), "
               "or from_raw<%s<%s>>(v) for data known to be unit length\n",
               kind, space, double(xyz.x), double(xyz.y), double(xyz.z), double(glm::length(xyz)), kind, space);
  std::abort();
}
#endif

/// Debug builds (checked, without NDEBUG) check that the components given to a direction
/// or normal are unit length: direction<S>(3, 0, 0) is a bug the type cannot see.
template <class S>
constexpr vec3_rep unit_length_checked(const char* kind, vec3_rep xyz) {
#if SAFEGI_CHECK_UNIT_LENGTH
  // Loose enough for components rounded to a few digits (0.577, 0.577, 0.577).
  const real squared = xyz.x * xyz.x + xyz.y * xyz.y + xyz.z * xyz.z;
  if (!(squared > real(1) - real(2e-3) && squared < real(1) + real(2e-3)))
    report_not_unit_length(kind, S::name.text, xyz);
#else
  (void)kind;
#endif
  return xyz;
}

/// The storage and raw access every three-component kind shares.
template <class Derived>
class vec3_storage {
 public:
  [[nodiscard]] constexpr vec3_rep raw_value() const { return xyz_; }

 protected:
  constexpr vec3_storage() = default;
  constexpr explicit vec3_storage(vec3_rep xyz) : xyz_(xyz) {}
  vec3_rep xyz_{real(0)};
};
}  // namespace detail

template <class S>
class basic_point : public detail::vec3_storage<basic_point<S>> {
  using base = detail::vec3_storage<basic_point<S>>;

 public:
  using space_type = S;
  constexpr basic_point() = default;
  /// Coordinates in S: a claim that they are S's (nothing checks it), so it is explicit and
  /// every claim spells its space where it is made: point<S>(x, y, z). from_raw<point<S>>(v)
  /// is the other (for data in reference units). Grep "point<" and "from_raw<" for them.
  constexpr explicit basic_point(quantity<dim::length> x, quantity<dim::length> y, quantity<dim::length> z)
      : base(vec3_rep(raw(x), raw(y), raw(z))) {}
  constexpr basic_point(detail::raw_tag, vec3_rep xyz) : base(xyz) {}
  // Conversions that are always mistakes; they exist so the error names both sides.
  template <class S2, class Report = diagnose::conversion_between_spaces<diagnose::kind::point, S2, S>>
    requires(!std::is_same_v<S2, S>)
  SAFEGI_MISTAKE basic_point(const basic_point<S2>& SAFEGI_REPORTED_AS(Report))
      SAFEGI_SAYS("cannot convert a point from one space into another by assignment: apply a map<From, To>");  // NOLINT
  template <class S2, class D, class Report = diagnose::wrong_geometric_kind<diagnose::kind::point, diagnose::kind::vector, S2>>
  SAFEGI_MISTAKE basic_point(const basic_vector<S2, D>& SAFEGI_REPORTED_AS(Report))
      SAFEGI_SAYS("a vector is not a point: p + v moves a point");  // NOLINT
  template <class S2, class Report = diagnose::wrong_geometric_kind<diagnose::kind::point, diagnose::kind::hpoint, S2>>
  SAFEGI_MISTAKE basic_point(const basic_hpoint<S2>& SAFEGI_REPORTED_AS(Report))
      SAFEGI_SAYS("an hpoint is not a point: dehomogenize(h)");  // NOLINT

  [[nodiscard]] constexpr quantity<dim::length> x() const { return detail::component<dim::length>(this->xyz_.x); }
  [[nodiscard]] constexpr quantity<dim::length> y() const { return detail::component<dim::length>(this->xyz_.y); }
  [[nodiscard]] constexpr quantity<dim::length> z() const { return detail::component<dim::length>(this->xyz_.z); }
  /// Component i (0, 1, 2), e.g. the split axis of a BVH.
  [[nodiscard]] constexpr quantity<dim::length> operator[](int i) const {
    return detail::component<dim::length>(this->xyz_[i]);
  }
};

template <class S, class D>
class basic_vector : public detail::vec3_storage<basic_vector<S, D>> {
  using base = detail::vec3_storage<basic_vector<S, D>>;

 public:
  using space_type = S;
  using dimension_type = D;
  constexpr basic_vector() = default;
  /// Components in S: a claim of the space, explicit like point<S>(x, y, z).
  constexpr explicit basic_vector(quantity<D> x, quantity<D> y, quantity<D> z)
      : base(vec3_rep(raw(x), raw(y), raw(z))) {}
  constexpr basic_vector(detail::raw_tag, vec3_rep xyz) : base(xyz) {}
  template <class S2, class E, class Report = diagnose::conversion_between_spaces<diagnose::kind::vector, S2, S>>
    requires(!std::is_same_v<S2, S>)
  SAFEGI_MISTAKE basic_vector(const basic_vector<S2, E>& SAFEGI_REPORTED_AS(Report))
      SAFEGI_SAYS("cannot convert a vector from one space into another by assignment: apply a map<From, To>");  // NOLINT
  template <class E, class Report = typename diagnose::report_if<!std::is_same_v<E, D>, diagnose::words_conversion_between_dimensions<E, D>>::type>
    requires(!std::is_same_v<E, D>)
  SAFEGI_MISTAKE basic_vector(const basic_vector<S, E>& SAFEGI_REPORTED_AS(Report))
      SAFEGI_SAYS("cannot convert a vector of one dimension into another");  // NOLINT

  [[nodiscard]] constexpr quantity<D> x() const { return detail::component<D>(this->xyz_.x); }
  [[nodiscard]] constexpr quantity<D> y() const { return detail::component<D>(this->xyz_.y); }
  [[nodiscard]] constexpr quantity<D> z() const { return detail::component<D>(this->xyz_.z); }
  [[nodiscard]] constexpr quantity<D> operator[](int i) const { return detail::component<D>(this->xyz_[i]); }

  constexpr basic_vector operator-() const { return {detail::raw_tag{}, -this->xyz_}; }
  constexpr basic_vector& operator+=(basic_vector other) {
    this->xyz_ += other.raw_value();
    return *this;
  }
  constexpr basic_vector& operator-=(basic_vector other) {
    this->xyz_ -= other.raw_value();
    return *this;
  }
  template <class S2, class E>
  diagnose::space_mismatch<diagnose::op::plus_assign, S, S2> operator+=(basic_vector<S2, E>);
  template <class E>
  typename diagnose::report_if<!std::is_same_v<D, E>, diagnose::words_dimension_mismatch<diagnose::op::plus_assign, D, E>>::type
  operator+=(basic_vector<S, E>);
  template <class S2, class E>
  diagnose::space_mismatch<diagnose::op::minus_assign, S, S2> operator-=(basic_vector<S2, E>);
  template <class E>
  typename diagnose::report_if<!std::is_same_v<D, E>, diagnose::words_dimension_mismatch<diagnose::op::minus_assign, D, E>>::type
  operator-=(basic_vector<S, E>);
  template <arithmetic U>
  constexpr basic_vector& operator*=(U factor) {
    this->xyz_ *= real(factor);
    return *this;
  }
  template <arithmetic U>
  constexpr basic_vector& operator/=(U divisor) {
    this->xyz_ /= real(divisor);
    return *this;
  }
};

template <class S>
class basic_direction : public detail::vec3_storage<basic_direction<S>> {
  using base = detail::vec3_storage<basic_direction<S>>;

 public:
  using space_type = S;
  constexpr basic_direction() : base(vec3_rep(real(0), real(0), real(1))) {}
  /// Components of a unit vector (not renormalised; use normalize(vector) otherwise).
  /// Debug builds stop the program if they are not unit length.
  constexpr explicit basic_direction(real x, real y, real z)
      : base(detail::unit_length_checked<S>("direction", vec3_rep(x, y, z))) {}
  constexpr basic_direction(detail::raw_tag, vec3_rep xyz) : base(xyz) {}
  template <class S2, class Report = diagnose::conversion_between_spaces<diagnose::kind::direction, S2, S>>
    requires(!std::is_same_v<S2, S>)
  SAFEGI_MISTAKE basic_direction(const basic_direction<S2>& SAFEGI_REPORTED_AS(Report))
      SAFEGI_SAYS("cannot convert a direction from one space into another by assignment: apply a map<From, To>");  // NOLINT
  template <class S2, class D, class Report = diagnose::wrong_geometric_kind<diagnose::kind::direction, diagnose::kind::vector_to_normalize, S2>>
  SAFEGI_MISTAKE basic_direction(const basic_vector<S2, D>& SAFEGI_REPORTED_AS(Report))
      SAFEGI_SAYS("a vector is not a direction: normalize(v)");  // NOLINT
  template <class S2, class Report = diagnose::wrong_geometric_kind<diagnose::kind::direction, diagnose::kind::normal, S2>>
  SAFEGI_MISTAKE basic_direction(const basic_normal<S2>& SAFEGI_REPORTED_AS(Report))
      SAFEGI_SAYS("a normal is not a direction: to_direction(n)");  // NOLINT

  [[nodiscard]] constexpr real x() const { return this->xyz_.x; }
  [[nodiscard]] constexpr real y() const { return this->xyz_.y; }
  [[nodiscard]] constexpr real z() const { return this->xyz_.z; }
  [[nodiscard]] constexpr real operator[](int i) const { return this->xyz_[i]; }
  constexpr basic_direction operator-() const { return {detail::raw_tag{}, -this->xyz_}; }
};

template <class S>
class basic_normal : public detail::vec3_storage<basic_normal<S>> {
  using base = detail::vec3_storage<basic_normal<S>>;

 public:
  using space_type = S;
  constexpr basic_normal() : base(vec3_rep(real(0), real(0), real(1))) {}
  /// Components of a unit normal (not renormalised). Debug builds stop the program if
  /// they are not unit length.
  constexpr explicit basic_normal(real x, real y, real z)
      : base(detail::unit_length_checked<S>("normal", vec3_rep(x, y, z))) {}
  constexpr basic_normal(detail::raw_tag, vec3_rep xyz) : base(xyz) {}
  template <class S2, class Report = diagnose::conversion_between_spaces<diagnose::kind::normal, S2, S>>
    requires(!std::is_same_v<S2, S>)
  SAFEGI_MISTAKE basic_normal(const basic_normal<S2>& SAFEGI_REPORTED_AS(Report))
      SAFEGI_SAYS("cannot convert a normal from one space into another by assignment: apply a map<From, To>");  // NOLINT
  template <class S2, class Report = diagnose::wrong_geometric_kind<diagnose::kind::normal, diagnose::kind::direction, S2>>
  SAFEGI_MISTAKE basic_normal(const basic_direction<S2>& SAFEGI_REPORTED_AS(Report))
      SAFEGI_SAYS("a direction is not a normal: to_normal(d)");  // NOLINT

  [[nodiscard]] constexpr real x() const { return this->xyz_.x; }
  [[nodiscard]] constexpr real y() const { return this->xyz_.y; }
  [[nodiscard]] constexpr real z() const { return this->xyz_.z; }
  [[nodiscard]] constexpr real operator[](int i) const { return this->xyz_[i]; }
  constexpr basic_normal operator-() const { return {detail::raw_tag{}, -this->xyz_}; }
};

template <class S>
class basic_hpoint {
 public:
  using space_type = S;
  constexpr basic_hpoint() = default;
  constexpr explicit basic_hpoint(real x, real y, real z, real w) : xyzw_(x, y, z, w) {}
  constexpr basic_hpoint(detail::raw_tag, vec4_rep xyzw) : xyzw_(xyzw) {}
  [[nodiscard]] constexpr vec4_rep raw_value() const { return xyzw_; }
  [[nodiscard]] constexpr real x() const { return xyzw_.x; }
  [[nodiscard]] constexpr real y() const { return xyzw_.y; }
  [[nodiscard]] constexpr real z() const { return xyzw_.z; }
  [[nodiscard]] constexpr real w() const { return xyzw_.w; }

 private:
  vec4_rep xyzw_{real(0), real(0), real(0), real(1)};
};

// ---- raw access

namespace detail {
template <class X, class Raw>
struct raw_access_by_member {
  using raw_type = Raw;
  static constexpr Raw to(const X& x) { return x.raw_value(); }
  static constexpr X from(Raw value) { return X(raw_tag{}, value); }
};
}  // namespace detail
template <class S>
struct raw_access<basic_point<S>> : detail::raw_access_by_member<basic_point<S>, vec3_rep> {};
template <class S, class D>
struct raw_access<basic_vector<S, D>> : detail::raw_access_by_member<basic_vector<S, D>, vec3_rep> {};
template <class S>
struct raw_access<basic_direction<S>> : detail::raw_access_by_member<basic_direction<S>, vec3_rep> {};
template <class S>
struct raw_access<basic_normal<S>> : detail::raw_access_by_member<basic_normal<S>, vec3_rep> {};
template <class S>
struct raw_access<basic_hpoint<S>> : detail::raw_access_by_member<basic_hpoint<S>, vec4_rep> {};

// ---- affine arithmetic

template <class S, class S2>
diagnose::space_mismatch<diagnose::op::minus, S, S2> operator-(basic_point<S>, basic_point<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr detail::displacement<S> operator-(basic_point<S> a, basic_point<S2> b) {
  return {detail::raw_tag{}, a.raw_value() - b.raw_value()};
}
template <class S, class S2, class D>
diagnose::space_mismatch<diagnose::op::plus, S, S2> operator+(basic_point<S>, basic_vector<S2, D>);
template <class S, class S2, class D>
  requires rules::same_space<S, S2> && (!rules::same_dimension<detail::length_dimension, D>)
diagnose::dimension_mismatch<diagnose::op::plus, in_words<detail::length_dimension>, in_words<D>,
                             ratio_in_words<detail::length_dimension, D>>
operator+(basic_point<S>, basic_vector<S2, D>);
template <class S, class S2, class D>
  requires rules::same_space<S, S2> && rules::same_dimension<detail::length_dimension, D>
constexpr basic_point<S> operator+(basic_point<S> p, basic_vector<S2, D> v) {
  return {detail::raw_tag{}, p.raw_value() + v.raw_value()};
}
template <class S, class S2, class D>
diagnose::space_mismatch<diagnose::op::plus, S2, S> operator+(basic_vector<S2, D>, basic_point<S>);
template <class S, class S2, class D>
  requires rules::same_space<S, S2> && (!rules::same_dimension<D, detail::length_dimension>)
diagnose::dimension_mismatch<diagnose::op::plus, in_words<D>, in_words<detail::length_dimension>,
                             ratio_in_words<D, detail::length_dimension>>
operator+(basic_vector<S2, D>, basic_point<S>);
template <class S, class S2, class D>
  requires rules::same_space<S, S2> && rules::same_dimension<detail::length_dimension, D>
constexpr basic_point<S> operator+(basic_vector<S2, D> v, basic_point<S> p) {
  return p + v;
}
template <class S, class S2, class D>
diagnose::space_mismatch<diagnose::op::minus, S, S2> operator-(basic_point<S>, basic_vector<S2, D>);
template <class S, class S2, class D>
  requires rules::same_space<S, S2> && (!rules::same_dimension<detail::length_dimension, D>)
diagnose::dimension_mismatch<diagnose::op::minus, in_words<detail::length_dimension>, in_words<D>,
                             ratio_in_words<detail::length_dimension, D>>
operator-(basic_point<S>, basic_vector<S2, D>);
template <class S, class S2, class D>
  requires rules::same_space<S, S2> && rules::same_dimension<detail::length_dimension, D>
constexpr basic_point<S> operator-(basic_point<S> p, basic_vector<S2, D> v) {
  return {detail::raw_tag{}, p.raw_value() - v.raw_value()};
}
template <class S, class S2>
diagnose::cannot_add_points<S> operator+(basic_point<S>, basic_point<S2>);
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::equal, S, S2> operator==(basic_point<S>, basic_point<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr bool operator==(basic_point<S> a, basic_point<S2> b) {
  return a.raw_value() == b.raw_value();
}

template <class S, class S2, class D, class E>
diagnose::space_mismatch<diagnose::op::plus, S, S2> operator+(basic_vector<S, D>, basic_vector<S2, E>);
template <class S, class S2, class D, class E>
  requires rules::same_space<S, S2> && (!rules::same_dimension<D, E>)
diagnose::dimension_mismatch<diagnose::op::plus, in_words<D>, in_words<E>, ratio_in_words<D, E>>
operator+(basic_vector<S, D>, basic_vector<S2, E>);
template <class S, class S2, class D, class E>
  requires rules::same_space<S, S2> && rules::same_dimension<D, E>
constexpr basic_vector<S, D> operator+(basic_vector<S, D> a, basic_vector<S2, E> b) {
  return {detail::raw_tag{}, a.raw_value() + b.raw_value()};
}
template <class S, class S2, class D, class E>
diagnose::space_mismatch<diagnose::op::minus, S, S2> operator-(basic_vector<S, D>, basic_vector<S2, E>);
template <class S, class S2, class D, class E>
  requires rules::same_space<S, S2> && (!rules::same_dimension<D, E>)
diagnose::dimension_mismatch<diagnose::op::minus, in_words<D>, in_words<E>, ratio_in_words<D, E>>
operator-(basic_vector<S, D>, basic_vector<S2, E>);
template <class S, class S2, class D, class E>
  requires rules::same_space<S, S2> && rules::same_dimension<D, E>
constexpr basic_vector<S, D> operator-(basic_vector<S, D> a, basic_vector<S2, E> b) {
  return {detail::raw_tag{}, a.raw_value() - b.raw_value()};
}
template <class S, class S2, class D, class E>
diagnose::space_mismatch<diagnose::op::equal, S, S2> operator==(basic_vector<S, D>, basic_vector<S2, E>);
template <class S, class S2, class D, class E>
  requires rules::same_space<S, S2> && (!rules::same_dimension<D, E>)
diagnose::dimension_mismatch<diagnose::op::equal, in_words<D>, in_words<E>, ratio_in_words<D, E>>
operator==(basic_vector<S, D>, basic_vector<S2, E>);
template <class S, class S2, class D, class E>
  requires rules::same_space<S, S2> && rules::same_dimension<D, E>
constexpr bool operator==(basic_vector<S, D> a, basic_vector<S2, E> b) {
  return a.raw_value() == b.raw_value();
}
template <class S, class D, class Q>
  requires quantity_like<Q> || arithmetic<Q>
constexpr auto operator*(basic_vector<S, D> v, Q factor) {
  using F = std::conditional_t<quantity_like<Q>, Q, real>;
  return basic_vector<S, dim::product<D, dimension_of<F>>>(detail::raw_tag{}, v.raw_value() * real(raw(F(factor))));
}
template <class S, class D, class Q>
  requires quantity_like<Q> || arithmetic<Q>
constexpr auto operator*(Q factor, basic_vector<S, D> v) {
  return v * factor;
}
template <class S, class D, class Q>
  requires quantity_like<Q> || arithmetic<Q>
constexpr auto operator/(basic_vector<S, D> v, Q divisor) {
  using F = std::conditional_t<quantity_like<Q>, Q, real>;
  return basic_vector<S, dim::quotient<D, dimension_of<F>>>(detail::raw_tag{}, v.raw_value() / real(raw(F(divisor))));
}

/// A unit vector scaled by a quantity: direction * (2.0f * units::metre) is a displacement.
template <class S, class Q>
  requires quantity_like<Q> || arithmetic<Q>
constexpr auto operator*(basic_direction<S> d, Q length) {
  using F = std::conditional_t<quantity_like<Q>, Q, real>;
  return basic_vector<S, dimension_of<F>>(detail::raw_tag{}, d.raw_value() * real(raw(F(length))));
}
template <class S, class Q>
  requires quantity_like<Q> || arithmetic<Q>
constexpr auto operator*(Q length, basic_direction<S> d) {
  return d * length;
}
template <class S, class Q>
  requires quantity_like<Q> || arithmetic<Q>
constexpr auto operator*(basic_normal<S> n, Q length) {
  using F = std::conditional_t<quantity_like<Q>, Q, real>;
  return basic_vector<S, dimension_of<F>>(detail::raw_tag{}, n.raw_value() * real(raw(F(length))));
}
template <class S, class Q>
  requires quantity_like<Q> || arithmetic<Q>
constexpr auto operator*(Q length, basic_normal<S> n) {
  return n * length;
}
/// The sum of two directions (e.g. the half vector wo + wi) is a dimensionless vector.
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::plus, S, S2> operator+(basic_direction<S>, basic_direction<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr basic_vector<S, dim::dimensionless> operator+(basic_direction<S> a, basic_direction<S2> b) {
  return {detail::raw_tag{}, a.raw_value() + b.raw_value()};
}
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::minus, S, S2> operator-(basic_direction<S>, basic_direction<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr basic_vector<S, dim::dimensionless> operator-(basic_direction<S> a, basic_direction<S2> b) {
  return {detail::raw_tag{}, a.raw_value() - b.raw_value()};
}
// Sums, differences and cross products of unit vectors with each other and with vectors,
// as the shader language has them (docs/language.md, "Geometric operations": any two of
// vector, direction and normal in one space, dimensions consistent, give a vector).
namespace detail {
template <class X>
struct unit_vector_traits {
  static constexpr bool value = false;
};
template <class S>
struct unit_vector_traits<basic_direction<S>> {
  static constexpr bool value = true;
  static constexpr bool is_direction = true;
  using space = S;
};
template <class S>
struct unit_vector_traits<basic_normal<S>> {
  static constexpr bool value = true;
  static constexpr bool is_direction = false;
  using space = S;
};
/// A direction or a normal: unit length, dimensionless.
template <class X>
concept unit_vector = unit_vector_traits<X>::value;
template <unit_vector U>
using space_of_unit = typename unit_vector_traits<U>::space;
/// Two unit vectors, at least one a normal (direction ± direction is above).
template <class A, class B>
concept unit_vector_pair_with_normal =
    unit_vector<A> && unit_vector<B> && !(unit_vector_traits<A>::is_direction && unit_vector_traits<B>::is_direction);
}  // namespace detail

/// normal ± normal, normal ± direction, direction ± normal: a dimensionless vector (an
/// averaged or bisecting normal before normalize, n - ng, the half vector ω + n).
template <class A, class B>
  requires detail::unit_vector_pair_with_normal<A, B>
diagnose::space_mismatch<diagnose::op::plus, detail::space_of_unit<A>, detail::space_of_unit<B>> operator+(A, B);
template <class A, class B>
  requires detail::unit_vector_pair_with_normal<A, B> &&
           rules::same_space<detail::space_of_unit<A>, detail::space_of_unit<B>>
constexpr basic_vector<detail::space_of_unit<A>, dim::dimensionless> operator+(A a, B b) {
  return {detail::raw_tag{}, a.raw_value() + b.raw_value()};
}
template <class A, class B>
  requires detail::unit_vector_pair_with_normal<A, B>
diagnose::space_mismatch<diagnose::op::minus, detail::space_of_unit<A>, detail::space_of_unit<B>> operator-(A, B);
template <class A, class B>
  requires detail::unit_vector_pair_with_normal<A, B> &&
           rules::same_space<detail::space_of_unit<A>, detail::space_of_unit<B>>
constexpr basic_vector<detail::space_of_unit<A>, dim::dimensionless> operator-(A a, B b) {
  return {detail::raw_tag{}, a.raw_value() - b.raw_value()};
}

/// vector<S, D> ± direction or normal, and direction or normal ± vector<S, D>: D must be
/// dimensionless, as a unit vector is; a displacement plus a unit vector lacks a length
/// (v + n where v + n * epsilon was meant).
template <class S, class D, detail::unit_vector U>
diagnose::space_mismatch<diagnose::op::plus, S, detail::space_of_unit<U>> operator+(basic_vector<S, D>, U);
template <class S, class D, detail::unit_vector U>
  requires rules::same_space<S, detail::space_of_unit<U>> && (!rules::same_dimension<D, dim::dimensionless>)
diagnose::dimension_mismatch<diagnose::op::plus, in_words<D>, in_words<dim::dimensionless>,
                             ratio_in_words<D, dim::dimensionless>>
operator+(basic_vector<S, D>, U);
template <class S, class D, detail::unit_vector U>
  requires rules::same_space<S, detail::space_of_unit<U>> && rules::same_dimension<D, dim::dimensionless>
constexpr basic_vector<S, D> operator+(basic_vector<S, D> v, U u) {
  return {detail::raw_tag{}, v.raw_value() + u.raw_value()};
}
template <class S, class D, detail::unit_vector U>
diagnose::space_mismatch<diagnose::op::minus, S, detail::space_of_unit<U>> operator-(basic_vector<S, D>, U);
template <class S, class D, detail::unit_vector U>
  requires rules::same_space<S, detail::space_of_unit<U>> && (!rules::same_dimension<D, dim::dimensionless>)
diagnose::dimension_mismatch<diagnose::op::minus, in_words<D>, in_words<dim::dimensionless>,
                             ratio_in_words<D, dim::dimensionless>>
operator-(basic_vector<S, D>, U);
template <class S, class D, detail::unit_vector U>
  requires rules::same_space<S, detail::space_of_unit<U>> && rules::same_dimension<D, dim::dimensionless>
constexpr basic_vector<S, D> operator-(basic_vector<S, D> v, U u) {
  return {detail::raw_tag{}, v.raw_value() - u.raw_value()};
}
template <class S, class D, detail::unit_vector U>
diagnose::space_mismatch<diagnose::op::plus, detail::space_of_unit<U>, S> operator+(U, basic_vector<S, D>);
template <class S, class D, detail::unit_vector U>
  requires rules::same_space<S, detail::space_of_unit<U>> && (!rules::same_dimension<dim::dimensionless, D>)
diagnose::dimension_mismatch<diagnose::op::plus, in_words<dim::dimensionless>, in_words<D>,
                             ratio_in_words<dim::dimensionless, D>>
operator+(U, basic_vector<S, D>);
template <class S, class D, detail::unit_vector U>
  requires rules::same_space<S, detail::space_of_unit<U>> && rules::same_dimension<D, dim::dimensionless>
constexpr basic_vector<S, D> operator+(U u, basic_vector<S, D> v) {
  return {detail::raw_tag{}, u.raw_value() + v.raw_value()};
}
template <class S, class D, detail::unit_vector U>
diagnose::space_mismatch<diagnose::op::minus, detail::space_of_unit<U>, S> operator-(U, basic_vector<S, D>);
template <class S, class D, detail::unit_vector U>
  requires rules::same_space<S, detail::space_of_unit<U>> && (!rules::same_dimension<dim::dimensionless, D>)
diagnose::dimension_mismatch<diagnose::op::minus, in_words<dim::dimensionless>, in_words<D>,
                             ratio_in_words<dim::dimensionless, D>>
operator-(U, basic_vector<S, D>);
template <class S, class D, detail::unit_vector U>
  requires rules::same_space<S, detail::space_of_unit<U>> && rules::same_dimension<D, dim::dimensionless>
constexpr basic_vector<S, D> operator-(U u, basic_vector<S, D> v) {
  return {detail::raw_tag{}, u.raw_value() - v.raw_value()};
}

template <class S, class S2>
diagnose::space_mismatch<diagnose::op::equal, S, S2> operator==(basic_direction<S>, basic_direction<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr bool operator==(basic_direction<S> a, basic_direction<S2> b) {
  return a.raw_value() == b.raw_value();
}
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::equal, S, S2> operator==(basic_normal<S>, basic_normal<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr bool operator==(basic_normal<S> a, basic_normal<S2> b) {
  return a.raw_value() == b.raw_value();
}

// ---- products

template <class S, class S2, class D, class E>
diagnose::space_mismatch<diagnose::op::dot, S, S2> dot(basic_vector<S, D>, basic_vector<S2, E>);
template <class S, class S2, class D, class E>
  requires rules::same_space<S, S2>
constexpr quantity<dim::product<D, E>> dot(basic_vector<S, D> a, basic_vector<S2, E> b) {
  return make_quantity<dim::product<D, E>, real>(glm::dot(a.raw_value(), b.raw_value()));
}
template <class S, class S2, class D, class E>
diagnose::space_mismatch<diagnose::op::cross, S, S2> cross(basic_vector<S, D>, basic_vector<S2, E>);
template <class S, class S2, class D, class E>
  requires rules::same_space<S, S2>
constexpr basic_vector<S, dim::product<D, E>> cross(basic_vector<S, D> a, basic_vector<S2, E> b) {
  return {detail::raw_tag{}, glm::cross(a.raw_value(), b.raw_value())};
}
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::dot, S, S2> dot(basic_direction<S>, basic_direction<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr real dot(basic_direction<S> a, basic_direction<S2> b) {
  return glm::dot(a.raw_value(), b.raw_value());
}
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::cross, S, S2> cross(basic_direction<S>, basic_direction<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr basic_vector<S, dim::dimensionless> cross(basic_direction<S> a, basic_direction<S2> b) {
  return {detail::raw_tag{}, glm::cross(a.raw_value(), b.raw_value())};
}
/// cross of a vector<S, D> and a direction or normal (either order): vector<S, D>; of two
/// unit vectors at least one of which is a normal: a dimensionless vector (a tangent
/// from a normal and a direction, cross(n, w)).
template <class S, class D, detail::unit_vector U>
diagnose::space_mismatch<diagnose::op::cross, S, detail::space_of_unit<U>> cross(basic_vector<S, D>, U);
template <class S, class D, detail::unit_vector U>
  requires rules::same_space<S, detail::space_of_unit<U>>
constexpr basic_vector<S, D> cross(basic_vector<S, D> v, U u) {
  return {detail::raw_tag{}, glm::cross(v.raw_value(), u.raw_value())};
}
template <class S, class D, detail::unit_vector U>
diagnose::space_mismatch<diagnose::op::cross, detail::space_of_unit<U>, S> cross(U, basic_vector<S, D>);
template <class S, class D, detail::unit_vector U>
  requires rules::same_space<S, detail::space_of_unit<U>>
constexpr basic_vector<S, D> cross(U u, basic_vector<S, D> v) {
  return {detail::raw_tag{}, glm::cross(u.raw_value(), v.raw_value())};
}
template <class A, class B>
  requires detail::unit_vector_pair_with_normal<A, B>
diagnose::space_mismatch<diagnose::op::cross, detail::space_of_unit<A>, detail::space_of_unit<B>> cross(A, B);
template <class A, class B>
  requires detail::unit_vector_pair_with_normal<A, B> &&
           rules::same_space<detail::space_of_unit<A>, detail::space_of_unit<B>>
constexpr basic_vector<detail::space_of_unit<A>, dim::dimensionless> cross(A a, B b) {
  return {detail::raw_tag{}, glm::cross(a.raw_value(), b.raw_value())};
}
/// The projected-cosine factor n·ω: the only way to get a quantity<dim::proj>.
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::dot, S, S2> dot(basic_normal<S>, basic_direction<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr quantity<dim::proj> dot(basic_normal<S> n, basic_direction<S2> w) {
  return make_quantity<mode_dimension<dim::proj>, real>(glm::dot(n.raw_value(), w.raw_value()));
}
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::dot, S, S2> dot(basic_direction<S>, basic_normal<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr quantity<dim::proj> dot(basic_direction<S> w, basic_normal<S2> n) {
  return dot(n, w);
}
/// |n·ω|, for two-sided surfaces.
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::dot, S, S2> abs_dot(basic_normal<S>, basic_direction<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr quantity<dim::proj> abs_dot(basic_normal<S> n, basic_direction<S2> w) {
  return safegi::abs(dot(n, w));
}
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::dot, S, S2> dot(basic_normal<S>, basic_normal<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr real dot(basic_normal<S> a, basic_normal<S2> b) {
  return glm::dot(a.raw_value(), b.raw_value());
}
template <class S, class S2, class D>
diagnose::space_mismatch<diagnose::op::dot, S, S2> dot(basic_direction<S>, basic_vector<S2, D>);
template <class S, class S2, class D>
  requires rules::same_space<S, S2>
constexpr quantity<D> dot(basic_direction<S> u, basic_vector<S2, D> v) {
  return make_quantity<D, real>(glm::dot(u.raw_value(), v.raw_value()));
}
template <class S, class S2, class D>
diagnose::space_mismatch<diagnose::op::dot, S2, S> dot(basic_vector<S2, D>, basic_direction<S>);
template <class S, class S2, class D>
  requires rules::same_space<S, S2>
constexpr quantity<D> dot(basic_vector<S2, D> v, basic_direction<S> u) {
  return dot(u, v);
}
template <class S, class S2, class D>
diagnose::space_mismatch<diagnose::op::dot, S, S2> dot(basic_normal<S>, basic_vector<S2, D>);
template <class S, class S2, class D>
  requires rules::same_space<S, S2>
constexpr quantity<D> dot(basic_normal<S> n, basic_vector<S2, D> v) {
  return make_quantity<D, real>(glm::dot(n.raw_value(), v.raw_value()));
}
template <class S, class S2, class D>
diagnose::space_mismatch<diagnose::op::dot, S2, S> dot(basic_vector<S2, D>, basic_normal<S>);
template <class S, class S2, class D>
  requires rules::same_space<S, S2>
constexpr quantity<D> dot(basic_vector<S2, D> v, basic_normal<S> n) {
  return dot(n, v);
}

// ---- lengths, normalisation, conversions between kinds

template <class S, class D>
constexpr quantity<D> length(basic_vector<S, D> v) {
  return make_quantity<D, real>(glm::length(v.raw_value()));
}
template <class S, class D>
constexpr quantity<dim::pow<D, 2>> length_squared(basic_vector<S, D> v) {
  return make_quantity<dim::pow<D, 2>, real>(glm::dot(v.raw_value(), v.raw_value()));
}
template <class S, class D>
constexpr basic_direction<S> normalize(basic_vector<S, D> v) {
  return {detail::raw_tag{}, glm::normalize(v.raw_value())};
}
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::minus, S, S2> distance(basic_point<S>, basic_point<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr quantity<dim::length> distance(basic_point<S> a, basic_point<S2> b) {
  return length(a - b);
}
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::minus, S, S2> distance_squared(basic_point<S>, basic_point<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr quantity<dim::area> distance_squared(basic_point<S> a, basic_point<S2> b) {
  return length_squared(a - b);
}
/// The point a + t (b - a).
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::lerp, S, S2> lerp(basic_point<S>, basic_point<S2>, real);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr basic_point<S> lerp(basic_point<S> a, basic_point<S2> b, real t) {
  return {detail::raw_tag{}, (real(1) - t) * a.raw_value() + t * b.raw_value()};
}
/// b0 p0 + b1 p1 + b2 p2 with b0 + b1 + b2 = 1 (a point on a triangle).
template <class S, class S1, class S2>
diagnose::space_mismatch<diagnose::op::barycentric, S, std::conditional_t<std::is_same_v<S, S1>, S2, S1>>
barycentric(basic_point<S>, basic_point<S1>, basic_point<S2>, real, real, real);
template <class S, class S1, class S2>
  requires rules::same_space<S, S1> && rules::same_space<S, S2>
constexpr basic_point<S> barycentric(basic_point<S> p0, basic_point<S1> p1, basic_point<S2> p2, real b0,
                                     real b1, real b2) {
  return {detail::raw_tag{}, b0 * p0.raw_value() + b1 * p1.raw_value() + b2 * p2.raw_value()};
}
/// Componentwise minimum and maximum of two points (bounding boxes).
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::min, S, S2> min(basic_point<S>, basic_point<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr basic_point<S> min(basic_point<S> a, basic_point<S2> b) {
  return {detail::raw_tag{}, glm::min(a.raw_value(), b.raw_value())};
}
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::max, S, S2> max(basic_point<S>, basic_point<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr basic_point<S> max(basic_point<S> a, basic_point<S2> b) {
  return {detail::raw_tag{}, glm::max(a.raw_value(), b.raw_value())};
}
/// Componentwise absolute value of a vector.
template <class S, class D>
constexpr basic_vector<S, D> abs(basic_vector<S, D> v) {
  return {detail::raw_tag{}, glm::abs(v.raw_value())};
}

/// The same unit vector, now transformed (and dotted) as a normal.
template <class S>
constexpr basic_normal<S> to_normal(basic_direction<S> d) {
  return {detail::raw_tag{}, d.raw_value()};
}
/// The same unit vector, now transformed (and dotted) as a direction.
template <class S>
constexpr basic_direction<S> to_direction(basic_normal<S> n) {
  return {detail::raw_tag{}, n.raw_value()};
}
/// n flipped into the hemisphere of w.
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::dot, S, S2> face_forward(basic_normal<S>, basic_direction<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr basic_normal<S> face_forward(basic_normal<S> n, basic_direction<S2> w) {
  return dot(n, w) < zero ? -n : n;
}
/// The mirror direction of w about n (both pointing away from the surface).
template <class S, class S2>
diagnose::space_mismatch<diagnose::op::reflect, S, S2> reflect(basic_direction<S>, basic_normal<S2>);
template <class S, class S2>
  requires rules::same_space<S, S2>
constexpr basic_direction<S> reflect(basic_direction<S> w, basic_normal<S2> n) {
  return {detail::raw_tag{}, -w.raw_value() + real(2) * glm::dot(w.raw_value(), n.raw_value()) * n.raw_value()};
}
/// The point an hpoint stands for (divides by w).
template <class S>
constexpr basic_point<S> dehomogenize(basic_hpoint<S> h) {
  const vec4_rep v = h.raw_value();
  return {detail::raw_tag{}, vec3_rep(v) / v.w};
}

}  // namespace SAFEGI_MODE_NAMESPACE

}  // namespace safegi

template <class S>
struct std::numeric_limits<safegi::SAFEGI_MODE_NAMESPACE::basic_point<S>>
    : safegi::diagnose::refused_numeric_limits<safegi::diagnose::kind::point, S> {};
template <class S, class D>
struct std::numeric_limits<safegi::SAFEGI_MODE_NAMESPACE::basic_vector<S, D>>
    : safegi::diagnose::refused_numeric_limits<safegi::diagnose::kind::vector, S> {};
template <class S>
struct std::numeric_limits<safegi::SAFEGI_MODE_NAMESPACE::basic_direction<S>>
    : safegi::diagnose::refused_numeric_limits<safegi::diagnose::kind::direction, S> {};
template <class S>
struct std::numeric_limits<safegi::SAFEGI_MODE_NAMESPACE::basic_normal<S>>
    : safegi::diagnose::refused_numeric_limits<safegi::diagnose::kind::normal, S> {};
template <class S>
struct std::numeric_limits<safegi::SAFEGI_MODE_NAMESPACE::basic_hpoint<S>>
    : safegi::diagnose::refused_numeric_limits<safegi::diagnose::kind::hpoint, S> {};

/// Declares a coordinate space in one line: SAFEGI_SPACE(world);
#define SAFEGI_SPACE(name) \
  struct name : ::safegi::space_tag<#name> {}
/// Declares the local space of frames built from a normal alone (arbitrary azimuth).
#define SAFEGI_NORMAL_FRAME_SPACE(name) \
  struct name : ::safegi::normal_frame_tag<#name> {}
/// Declares the local space of tangent frames (+x along dp/du).
#define SAFEGI_TANGENT_FRAME_SPACE(name) \
  struct name : ::safegi::tangent_frame_tag<#name> {}
