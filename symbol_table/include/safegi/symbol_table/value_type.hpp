#pragma once
// The one description of a value's type shared by both sides of a binding: the
// shader side comes from the symbol table, the host side from value_traits<T>.
// Comparing two descriptions and printing them in words lives here, without GL.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace safegi::gl {

// Base-dimension name -> non-zero exponent. Empty means dimensionless.
using DimensionExponents = std::map<std::string, int>;

struct Dimension {
  DimensionExponents exponents;
  std::string name;  // printed name when known ("radiance"); empty otherwise
  // A name that yields to the symbol table's own name for these exponents
  // (host types: the shader's vocabulary is what the user reads).
  bool name_is_hint = false;
  friend bool operator==(const Dimension& a, const Dimension& b) { return a.exponents == b.exponents; }
};

// What a value is geometrically. `plain` is an unannotated GLSL type.
enum class Kind {
  plain, scalar, spectrum, point, vector, direction, normal, hpoint, map, projective_map, sampler, block
};

std::string_view to_string(Kind kind);
std::optional<Kind> kind_from_string(std::string_view text);

struct ValueType {
  Kind kind = Kind::plain;
  std::string glsl_type;            // "vec3", "float", "mat4", "sampler2D"
  Dimension dimension;              // for scalar and spectrum (others: empty)
  std::vector<std::string> spaces;  // point/vector/...: one; map: {from, to}
};

// Names exponent vectors for messages: the dimension's own name, a derived
// dimension whose exponents match ("radiance"), or a product of bases
// ("energy*length^-2"). Dimensionless prints as "1".
class DimensionNamer {
 public:
  DimensionNamer() = default;
  void add(std::string name, DimensionExponents exponents);
  std::string name(const Dimension& dimension) const;

 private:
  std::vector<std::pair<std::string, DimensionExponents>> derived_;
};

// "spectrum<radiance>", "point<world>", "map<object, world>", "float<length>",
// "float", "vec3", "sampler2D<spectrum<radiance>>".
std::string in_words(const ValueType& type, const DimensionNamer& namer,
                     const ValueType* texel = nullptr);

// Empty when the types agree; otherwise which parts differ, in words
// ("kind", "GLSL type", "dimension", "space"). A dimensionless scalar is the
// plain scalar, and a vector without a dimension is a length.
std::vector<std::string> differences(const ValueType& shader, const ValueType& host);

}  // namespace safegi::gl
