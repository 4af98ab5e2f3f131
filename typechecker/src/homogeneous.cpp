// The homogeneous idioms of real GLSL (docs/language.md, "Homogeneous idioms"):
// `(m * vec4(p, 1.0)).xyz` applies a map to a point, `m * vec4(v, 0.0)` to a
// vector, `vec4(n, 0.0) * inverse(m)` carries a normal by the inverse
// transpose, and `transpose(inverse(m))` is the normal matrix of m. The checker
// reads w = 1 as a point and w = 0 as a vector, direction or normal, so a
// normal taken through the model matrix, or given w = 1, is told as such.

#include "checker_impl.hpp"
#include "dim_slot.hpp"

namespace safegi::detail {
namespace {

bool vectorish(Geometry g) { return g == Geometry::vector || g == Geometry::direction || g == Geometry::normal; }

bool is_vec4(const Type& t) {
  return t.shape == Shape::vector && t.rows == 4 && t.is_floating() && !t.is_array() && t.geometry == Geometry::none;
}

}  // namespace

// vec4(x, 1.0) of a point, vec4(x, 0.0) of a vector, direction or normal: the vec4 remembers x.
void Checker::remember_affine_part(Type& vec4, const std::vector<Value>& args) const {
  if (!is_vec4(vec4) || args.size() != 2) return;
  const Type& x = args[0].type;
  if (x.shape != Shape::vector || x.rows != 3 || x.is_array() || !(x.geometry == Geometry::point || vectorish(x.geometry)))
    return;
  const std::optional<double> w = args[1].number;
  if (!w || (*w != 0.0 && *w != 1.0) || args[1].type.shape != Shape::scalar) return;
  vec4.affine = std::make_shared<const Type>(x);
  vec4.affine_w = static_cast<std::int8_t>(*w);
}

// `.xyz` (`.rgb`, `.stp`) or vec3(v) of a vec4 that remembers its x: x, moved by the maps applied since.
std::optional<Type> Checker::affine_part(const Type& vec4, const std::string& swizzle) const {
  if (!vec4.affine || vec4.is_array()) return std::nullopt;
  if (swizzle != "xyz" && swizzle != "rgb" && swizzle != "stp") return std::nullopt;
  return *vec4.affine;
}

// transpose(m) and inverse(m) of a map or a normal matrix: the normal matrix of m is
// transpose(inverse(m)); transposing twice, or inverting, keeps what the matrix carries.
std::optional<Value> Checker::map_matrix_call(const std::string& name, const std::vector<Value>& args, SourceRange call_range) {
  if ((name != "transpose" && name != "inverse") || args.size() != 1) return std::nullopt;
  const Type& m = args[0].type;
  if (!is_map(m.geometry) || m.is_array() || m.geometry == Geometry::projmap) return std::nullopt;
  if (name == "inverse" && !m.normal_matrix) return std::nullopt;  // the table's inverse(map<S, T>) -> map<T, S>
  Value out;
  out.range = call_range;
  out.type = m;
  std::swap(out.type.from, out.type.to);
  if (name == "transpose") out.type.normal_matrix = !m.normal_matrix;
  return out;
}

// m * v and v * m with a 4×4 map and a vec4; nothing when the operands are no such pair.
std::optional<Value> Checker::homogeneous_application(const Value& lhs, const Value& rhs, SourceRange op_range, SourceRange range) {
  const bool row = is_vec4(lhs.type) && is_map(rhs.type.geometry);
  if (!row && !(is_map(lhs.type.geometry) && is_vec4(rhs.type))) return std::nullopt;
  const Value& map = row ? rhs : lhs;
  const Value& v = row ? lhs : rhs;
  const Type& m = map.type;
  if (m.shape != Shape::matrix || m.rows != 4 || m.columns != 4 || m.is_array()) return std::nullopt;
  Value out;
  out.range = range;
  out.type = Type::vector_of(v.type.scalar, 4);
  if (!v.type.affine) {
    // An unannotated vec4 under a map: gradual, as plain GLSL (a projmap's result is homogeneous).
    if (m.geometry != Geometry::projmap || row) return out;
    return std::nullopt;  // projmap * vec4: the table's hpoint rule
  }
  const Type& x = *v.type.affine;
  const int w = v.type.affine_w;
  auto reject = [&](const std::string& message, const std::string& hint, const char* code) {
    operand_mismatch(message, lhs, rhs, op_range, hint, code);
    return std::optional<Value>(error_value(range));
  };
  // The names a hint writes code with: the program's own where the operand is one.
  const std::string m_name = map.name.empty() ? "m" : map.name;
  const std::string x_name = "n";
  const std::string kind = geometry_name(x.geometry);
  const bool normal = x.geometry == Geometry::normal;
  // What the matrix carries, and between which spaces, as applied: v * m is transpose(m) * v.
  const bool carries_normals = m.normal_matrix != row;  // transpose(map<A, B>) carries normals from B to A
  const SpaceSlot source = row ? m.to : m.from, target = row ? m.from : m.to;
  const bool rigid = m.geometry == Geometry::rigidmap;

  if (x.geometry == Geometry::point && w != 1)
    return reject("cannot apply " + name_of(m) + " to " + name_of(v.type) + ": a point needs w = 1, and w = 0 drops the map's translation",
                  "write vec4(p, 1.0) for a point (w = 0 is for vectors, directions and normals)", code::E_KIND_MISMATCH);
  if (x.geometry != Geometry::point && w != 0)
    return reject("cannot apply " + name_of(m) + " to " + name_of(v.type) + ": a " + kind + " needs w = 0, and w = 1 adds the map's translation to it",
                  "write vec4(v, 0.0) for a " + kind + " (w = 1 is for points)", code::E_KIND_MISMATCH);
  if (!consistent(x.from, source))
    return reject("cannot apply " + name_of(m) + " to " + name_of(v.type) + ": the " + (row ? "transposed " : "") + "map takes values in " +
                      name_of_space(source) + ", not in " + name_of_space(x.from),
                  row ? "v * m multiplies by the transpose of m: a map applies as m * v" : space_hint(source, x.from),
                  code::E_SPACE_MISMATCH);
  if (m.geometry == Geometry::projmap && !row) {
    if (normal)
      return reject("cannot project " + name_of(v.type) + " with " + name_of(m) + ": a normal is no position", "", code::E_KIND_MISMATCH);
    out.type.geometry = Geometry::hpoint;
    out.type.from = target;
    return out;
  }
  if (carries_normals && !rigid && !normal)
    return reject("cannot apply " + std::string(row ? "the transpose of " : "") + name_of(m) + " to " + name_of(v.type) +
                      ": the inverse transpose carries normals, not a " + kind,
                  row ? "v * m multiplies by the transpose of m: a map applies as m * v" : "apply the map itself to a " + kind,
                  code::E_KIND_MISMATCH);
  if (normal && !carries_normals && !rigid)
    return reject("cannot apply " + name_of(m) + " to " + name_of(v.type) +
                      ": a normal transforms by the inverse transpose of the map, and this map may scale or shear",
                  "carry it by the inverse transpose: vec4(" + x_name + ", 0.0) * inverse(" + m_name + "), or transpose(inverse(" +
                      m_name + ")) * vec4(" + x_name + ", 0.0)",
                  code::E_KIND_MISMATCH);
  Type moved = x;
  moved.from = target;
  if (x.geometry == Geometry::direction && !rigid) {
    moved.geometry = Geometry::vector;  // a scaled direction is no longer of unit length
    moved.dim = DimSlot::known(Dimension{});
  }
  out.type.affine = std::make_shared<const Type>(moved);
  out.type.affine_w = static_cast<std::int8_t>(w);
  return out;
}

}  // namespace safegi::detail
