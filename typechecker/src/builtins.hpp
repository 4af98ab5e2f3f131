#pragma once
// The built-in function library (builtins.def) parsed into signatures over the
// checker's types, and matching of a call's argument types against them.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "safegi/typechecker/type.hpp"

namespace safegi {

// How a built-in is typed: by its signature, or by a rule for families whose
// result depends on an opaque argument.
enum class BuiltinRule : std::uint8_t {
  plain,             // the signature says everything
  pow,               // genF<1> ^ genF<1>, or float<D> ^ integer constant n -> float<D^n>
  angle_unit,        // radians/degrees: also an angle in the other unit -> that angle in this one (dimension_rules.cpp)
  normal_transform,  // a normal through a non-rigid map: the elider uses the inverse transpose
  point_misuse,      // a point where the function needs a vector: matching this row is an error (E-POINT-ARITHMETIC)
  texture,           // texture*(sampler<T>, ...) -> the sampler's texel, as gvec4 (or float for shadow)
  texture_size,      // textureSize / imageSize -> int or ivecN by the sampler's dimensionality
  texture_query,     // textureQueryLod -> vec2; textureQueryLevels, textureSamples -> int
  image,             // imageLoad -> gvec4, imageStore -> void, imageAtomic* -> int/uint
  atomic_counter,    // atomicCounter*(atomic_uint) -> uint
};

// How a signature's parameter or result sizes itself.
enum class SizeClass : std::uint8_t { fixed, gen, vec, mat, mat_transposed, mat_square, column, row };

struct SigType {
  SizeClass size = SizeClass::fixed;
  Type type;              // shape/scalar/sizes for fixed; scalar for the others; annotation slots (generic)
  bool any_geometric = false;  // geo<S, D>: vector, direction or normal
  bool is_out = false;    // out / inout: the argument must be an l-value of exactly this type
};

struct Signature {
  std::string name;
  BuiltinRule rule = BuiltinRule::plain;
  std::vector<SigType> params;
  SigType result;
  std::vector<std::string> dim_params;    // D, E
  std::vector<std::string> space_params;  // S, T, U
  std::string text;                       // the signature as written in builtins.def
};

class BuiltinLibrary {
 public:
  // Resolves the dimension names the signatures use in `registry`; names the
  // program does not declare make that slot unknown.
  explicit BuiltinLibrary(const DimensionRegistry& registry);
  // The library for `registry`, shared by every program whose base and derived
  // dimensions are the same (e.g. all that include the prelude): parsing the
  // ~300 signatures dominated checking a small shader. Thread-safe; the
  // libraries are immutable.
  static std::shared_ptr<const BuiltinLibrary> for_registry(const DimensionRegistry& registry);

  const std::vector<Signature>* find(std::string_view name) const;
  bool is_builtin(std::string_view name) const { return find(name) != nullptr; }

 private:
  std::unordered_map<std::string, std::vector<Signature>> by_name_;
};

// What the checker asks of a built-in's arguments beyond their signature (builtin_argument_rules.def).
enum class ArgumentRule : std::uint8_t { unit_length, no_angle_triples, divided_only };
bool builtin_argument_rule(std::string_view name, ArgumentRule rule);

// Rules typed by their signature text (the others are typed by code from an opaque argument).
inline bool has_signature(BuiltinRule r) {
  return r == BuiltinRule::plain || r == BuiltinRule::pow || r == BuiltinRule::angle_unit || r == BuiltinRule::normal_transform || r == BuiltinRule::point_misuse;
}

// One call argument as matching sees it.
struct ArgInfo {
  Type type;
  bool lvalue = false;
};

struct ShapeMatch {
  const Signature* signature = nullptr;
  int n = 1, columns = 1, rows = 1;  // bound sizes
  int cost = 0;                      // implicit conversions + geometry dropped
  // The width the signature's float, int and uint words stand for: a row over genF also takes
  // float16_t, one over genI and genU the 8-, 16- and 64-bit integers, all of one width, as
  // glslang's overloads for the explicit arithmetic types do (docs/language.md). A fixed
  // parameter type (`float`, `int`) is of that width for an argument of it, else of its own.
  Scalar float_as = Scalar::float_, int_as = Scalar::int_, uint_as = Scalar::uint_;
  Scalar width_of(Scalar s) const {
    return s == Scalar::float_ ? float_as : s == Scalar::int_ ? int_as : s == Scalar::uint_ ? uint_as : s;
  }
};

// The best signature whose GLSL shapes (and geometric kinds) accept the
// arguments, or nothing. Annotations (dimensions, spaces) are not looked at.
std::optional<ShapeMatch> match_shapes(const std::vector<Signature>& candidates, const std::vector<ArgInfo>& args);

// The concrete type a signature type stands for under the bound sizes and width, with
// its annotation slots left as written (generic). A fixed parameter type (`int` of
// bitfieldExtract) is left as written; a result takes the call's width (`length(f16vec3)` is a float16_t).
Type instantiate_shape(const SigType& t, const ShapeMatch& m, bool result = false);

// The dimension and kind a value brings to a numeric parameter: directions and
// normals are dimensionless, points are lengths.
DimSlot value_dimension(const Type& t, const DimensionRegistry& registry);

}  // namespace safegi
