#pragma once
// The checker's types: a GLSL type (shape + scalar + arrays) with SafeGI's
// annotation on top: a geometric kind, a dimension and up to two spaces, and a
// sampler's texel type. Each annotation slot may be unknown (`?`, unannotated
// GLSL), known, the zero literal (fits any dimension), or generic (a template
// parameter of a function being declared or called).

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "safegi/dimension_algebra/registry.hpp"
#include "safegi/dimension_algebra/unifier.hpp"

namespace safegi {

enum class Shape : std::uint8_t { error, void_, scalar, vector, matrix, opaque, structure };
// int_, uint_, float_ and double_ are GLSL's 32- and 64-bit types (int32_t, float64_t, ... are other
// names of them); the others are the 8-, 16- and 64-bit types of GL_EXT_shader_explicit_arithmetic_types
// and the extensions before it (docs/language.md, "Explicit arithmetic types").
enum class Scalar : std::uint8_t { none, bool_, int_, uint_, float_, double_, int8_, uint8_, int16_, uint16_, int64_, uint64_, float16_ };

// Bytes of one component (bool: 4, as GLSL lays it out).
int scalar_bytes(Scalar s);
bool is_float_scalar(Scalar s);
bool is_integer_scalar(Scalar s);

// What an annotated type word says about a value (docs/language.md, "Annotated types").
enum class Geometry : std::uint8_t {
  none,       // float, vecN, ...: only a dimension
  spectrum,   // vec3 of one dimension
  point,      // vec3, length, in a space
  vector,     // vec3 of a dimension (length by default), in a space
  direction,  // unit vec3, dimensionless, in a space
  normal,     // unit vec3 transforming by the inverse transpose, in a space
  hpoint,     // vec4 homogeneous point in a space
  map,        // mat4, space A -> space B
  rigidmap,   // mat4, rigid, A -> B
  projmap,    // mat4, projective, A -> hpoint in B
};

// Which way a vector or direction points, relative to the point being shaded
// (docs/language.md, "Orientation"): `away` from it, as renderers' wi and wo,
// or `toward` it, as GLSL's incident I. A point may be marked as that point
// itself (`shaded`), which orients a difference of it and another point.
// `none` (unwritten) is consistent with every orientation.
enum class Orientation : std::uint8_t { none, away, toward, shaded };

const char* orientation_name(Orientation o);
// away <-> toward (negation); none and shaded stay.
Orientation flipped(Orientation o);
// Both known and different: a direction toward the shaded point where one away from it is expected.
inline bool orientations_clash(Orientation a, Orientation b) {
  return a != Orientation::none && b != Orientation::none && a != b;
}

const char* geometry_name(Geometry g);
bool has_space(Geometry g);
bool is_map(Geometry g);
// A vector, direction or normal: a displacement, with no position.
bool vectorish(Geometry g);
// A value of kind `value` may stand where kind `wanted` is expected: the same
// kind, or a rigidmap where a map is expected (a rigid map is affine).
bool kind_fits(Geometry value, Geometry wanted);

struct DimSlot {
  enum class State : std::uint8_t { unknown, known, zero, generic };
  State state = State::unknown;
  Dimension value;      // known
  DimTerm term;         // generic: over the template's dimension parameters
  std::string spelling; // the name an annotation used (`pdf_projected_solid_angle`), for display

  static DimSlot unknown() { return {}; }
  static DimSlot known(Dimension d, std::string spelling = {}) { return {State::known, std::move(d), {}, std::move(spelling)}; }
  static DimSlot zero() { return {State::zero, {}, {}, {}}; }
  static DimSlot generic(DimTerm t) { return {State::generic, {}, std::move(t), {}}; }
  bool is_known() const { return state == State::known; }
};

struct SpaceSlot {
  enum class State : std::uint8_t { unknown, known, generic };
  State state = State::unknown;
  std::uint32_t id = 0;  // SpaceId when known, template parameter index when generic
  static SpaceSlot unknown() { return {}; }
  static SpaceSlot known(SpaceId s) { return {State::known, s}; }
  static SpaceSlot generic(std::uint32_t v) { return {State::generic, v}; }
  bool is_known() const { return state == State::known; }
  friend bool operator==(const SpaceSlot&, const SpaceSlot&) = default;
};

struct StructInfo;

struct Type {
  Shape shape = Shape::error;
  Scalar scalar = Scalar::none;
  std::uint8_t rows = 1;          // vector size, or matrix rows
  std::uint8_t columns = 1;       // matrix columns
  std::string opaque;             // sampler2D, image2D, atomic_uint, ...
  const StructInfo* structure = nullptr;
  std::vector<int> array;         // outermost first; -1 unsized
  // Annotation.
  Geometry geometry = Geometry::none;
  DimSlot dim;
  SpaceSlot from;                 // the space (or a map's source space)
  SpaceSlot to;                   // a map's target space
  std::shared_ptr<const Type> texel;  // annotated sampler
  // Geometry::hpoint: the power of w its components carry. An hpoint and its
  // swizzles (h.xy, h.w) have 1, 1.0 / h.w has -1; a value of weight 0 is no
  // longer homogeneous (h.xy / h.w), so it loses the kind.
  std::int8_t weight = 1;
  // Geometry::vector and direction: away or toward; Geometry::point: shaded.
  Orientation orientation = Orientation::none;
  // A plain vec4 built as (x, w) from a point (w = 1) or a vector, direction or normal
  // (w = 0): what its xyz is, so `(m * vec4(p, 1.0)).xyz` is m applied to p
  // (docs/language.md, "Homogeneous idioms"). `affine_w` is 0 or 1 when `affine` is set.
  std::shared_ptr<const Type> affine;
  std::int8_t affine_w = 0;
  // A map's matrix that is the inverse transpose of the map from `from` to `to`
  // (transpose(inverse(m))): it carries normals from `from` to `to`, as vec4(n, 0.0).
  bool normal_matrix = false;
  // Geometry::normal: why it is not of unit length until normalize() (docs/language.md,
  // "What spaces do not reach"): interpolated across a primitive (a fragment shader's
  // input), carried by a normal matrix that may scale, or filtered by a texture lookup
  // (a G-buffer's normal read with texture(); texelFetch reads it as stored), or offset by an
  // unannotated vector (a morph target's `n + dn`), or summed from normals (a blend `w0 * n0 + w1 * n1`).
  enum class LengthLoss : std::uint8_t { none, interpolated, scaled, filtered, offset, blended };
  LengthLoss length_loss = LengthLoss::none;
  // Geometry::vector: a plain multiple of a normal (`w * n`) or a difference of two (`m - n`): a
  // vector with a length, which added to a normal or another such multiple is a normal again
  // (normals are covectors: their weighted sums are normals), unit only once normalized.
  bool normal_multiple = false;

  static Type error() { return {}; }
  static Type void_type() { Type t; t.shape = Shape::void_; return t; }
  static Type scalar_of(Scalar s) { Type t; t.shape = Shape::scalar; t.scalar = s; return t; }
  static Type vector_of(Scalar s, int n) {
    Type t; t.shape = n == 1 ? Shape::scalar : Shape::vector; t.scalar = s; t.rows = static_cast<std::uint8_t>(n); return t;
  }
  static Type matrix_of(Scalar s, int columns, int rows) {
    Type t; t.shape = Shape::matrix; t.scalar = s; t.columns = static_cast<std::uint8_t>(columns);
    t.rows = static_cast<std::uint8_t>(rows); return t;
  }

  bool is_error() const { return shape == Shape::error; }
  bool is_array() const { return !array.empty(); }
  bool is_numeric() const { return (shape == Shape::scalar || shape == Shape::vector || shape == Shape::matrix) && scalar != Scalar::bool_; }
  bool is_floating() const { return is_float_scalar(scalar); }
  bool is_integer() const { return is_integer_scalar(scalar); }
  bool is_annotated() const {
    return geometry != Geometry::none || dim.state == DimSlot::State::known || texel != nullptr || affine != nullptr;
  }
  int components() const { return shape == Shape::matrix ? rows * columns : rows; }
  // The same GLSL type with every annotation slot unknown.
  Type plain() const;
  // The element type of an array, or a type without its outermost array dimension.
  Type element() const;
};

struct StructField {
  std::string name;
  Type type;
  bool read_only = false;  // a `readonly` member of a buffer_reference block
};

struct StructInfo {
  std::string name;
  std::vector<StructField> fields;
  // GL_EXT_buffer_reference: a `layout(buffer_reference) buffer B { … };`
  // block, whose name is the type of a 64-bit reference to such memory.
  bool buffer_reference = false;
  bool read_only = false;  // `layout(buffer_reference) readonly buffer B`: the memory it refers to
};

// Same GLSL type (shape, scalar, sizes, arrays, struct, opaque name), ignoring annotations.
bool same_glsl_type(const Type& a, const Type& b);
// GLSL's implicit conversion of the scalar type (int -> uint -> float -> double), with the
// explicit arithmetic types' (glslang's canImplicitlyPromote: int8 -> int16 -> int -> int64,
// integers to floats at least as wide, float16 -> float -> double).
bool implicitly_converts(Scalar from, Scalar to);
// The scalar type two operands of a binary operator are converted to, or nothing: the one the
// other converts to, else a signed and a narrower unsigned integer meet at the signed one's
// unsigned twin (int + uint8_t is uint), as glslang does (float + int64_t has none).
std::optional<Scalar> common_scalar(Scalar a, Scalar b);

// The GLSL spelling: float, vec3, mat4x3, sampler2D, S, float[4].
std::string glsl_name(const Type& t);
// The annotated spelling in the user's words: float<radiance>, point<world>,
// map<object, world>, spectrum<?>, vec3. Generic slots print the parameter names.
std::string type_name(const Type& t, const DimensionRegistry& registry,
                      const std::vector<std::string>* dim_params = nullptr,
                      const std::vector<std::string>* space_params = nullptr);
// A space in the program's words: its name, a template parameter's name, or `?`.
std::string space_text(const SpaceSlot& s, const DimensionRegistry& registry,
                       const std::vector<std::string>* space_params = nullptr);
std::string dim_name(const DimSlot& d, const DimensionRegistry& registry,
                     const std::vector<std::string>* dim_params = nullptr);

}  // namespace safegi
