// The homogeneous idioms of real GLSL (docs/language.md, "Homogeneous idioms"):
// `(m * vec4(p, 1.0)).xyz` applies a map to a point, `m * vec4(v, 0.0)` to a
// vector, `vec4(n, 0.0) * inverse(m)` carries a normal by the inverse
// transpose, and `transpose(inverse(m))` is the normal matrix of m. The checker
// reads w = 1 as a point and w = 0 as a vector, direction or normal, so a
// normal taken through the model matrix, or given w = 1, is told as such.

#include <algorithm>

#include "checker_impl.hpp"
#include "dim_slot.hpp"

namespace safegi::detail {

namespace {

// "X" of a spelling "transpose(X)" whose parentheses close at its end; empty otherwise.
std::string transposed_argument(const std::string& text) {
  const std::string head = "transpose(";
  if (text.size() <= head.size() + 1 || text.compare(0, head.size(), head) != 0 || text.back() != ')') return {};
  int depth = 0;
  for (std::size_t i = head.size() - 1; i < text.size(); ++i) {
    depth += text[i] == '(' ? 1 : text[i] == ')' ? -1 : 0;
    if (depth == 0 && i + 1 != text.size()) return {};
  }
  return text.substr(head.size(), text.size() - head.size() - 1);
}

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

// A column of an affine map<A, B> (`m[0]` … `m[3]`): the first three are A's axes as vectors of B
// (unit directions under a rigidmap), the last A's origin as a point of B — as vec4s (w 0 and 1) of
// a 4×4 map, whose `.xyz` is that, or the vector itself of a 3×3 one. A normal matrix's columns and a
// projective map's are not: they stay plain.
void Checker::map_column(Type& column, const Type& map, long long index) const {
  if ((map.geometry != Geometry::map && map.geometry != Geometry::rigidmap) || map.normal_matrix || map.is_array() ||
      map.columns != map.rows || (map.rows != 3 && map.rows != 4) || index < 0 || index >= map.columns || !map.to.is_known())
    return;
  Type part = Type::vector_of(map.scalar, 3);
  part.from = map.to;
  if (index == 3) {
    part.geometry = Geometry::point;
  } else {
    part.geometry = map.geometry == Geometry::rigidmap ? Geometry::direction : Geometry::vector;
    part.dim = DimSlot::known(Dimension{});
  }
  if (part.geometry == Geometry::point) part.dim = value_dimension(part, result_.registry);
  if (map.rows == 3) {
    column = part;
    return;
  }
  column.affine = std::make_shared<const Type>(part);
  column.affine_w = index == 3 ? 1 : 0;
}

// `.xyz` (`.rgb`, `.stp`) or vec3(v) of a vec4 that remembers its x: x, moved by the maps applied since.
std::optional<Type> Checker::affine_part(const Type& vec4, const std::string& swizzle) const {
  if (!vec4.affine || vec4.is_array()) return std::nullopt;
  if (swizzle != "xyz" && swizzle != "rgb" && swizzle != "stp") return std::nullopt;
  return *vec4.affine;
}

// (p, 1) - (q, 1) is the vector (p - q, 0), (p, 1) + (v, 0) the point (p + v, 1): sums and
// differences of vec4s that remember their xyz keep it when w comes out as the kind needs
// (1 for a point, 0 for a vector); a w left at 1 on a vector (`(l, 1) - vec4(p, 0.0)`, the
// stray w that then reaches length()) is told. Nothing when either operand is no such vec4.
std::optional<Value> Checker::affine_sum(ast::BinaryOp op, const Value& lhs, const Value& rhs, SourceRange op_range, SourceRange range) {
  if ((op != ast::BinaryOp::Add && op != ast::BinaryOp::Sub) || !lhs.type.affine || !rhs.type.affine) return std::nullopt;
  const bool add = op == ast::BinaryOp::Add;
  Value x = lhs, y = rhs;
  x.type = *lhs.type.affine;
  y.type = *rhs.type.affine;
  Value xyz = arithmetic(nullptr, op, x, y, op_range, range);  // the 3D rules: point + point, spaces, dimensions
  if (xyz.type.is_error()) return error_value(range);
  const int w = add ? lhs.type.affine_w + rhs.type.affine_w : lhs.type.affine_w - rhs.type.affine_w;
  const int wanted = xyz.type.geometry == Geometry::point ? 1 : 0;
  if (w != wanted) {
    operand_mismatch(std::string("cannot ") + (add ? "add " : "subtract ") + name_of(rhs.type) + (add ? " to " : " from ") +
                         name_of(lhs.type) + ": the result's homogeneous w is " + std::to_string(w) + ", and a " +
                         geometry_name(xyz.type.geometry) + " needs w = " + std::to_string(wanted),
                     lhs, rhs, op_range,
                     "give each point w = 1 and each vector w = 0, or subtract the xyz parts (a.xyz - b.xyz)", code::E_KIND_MISMATCH);
    return error_value(range);
  }
  Value out;
  out.range = range;
  out.type = Type::vector_of(lhs.type.scalar, 4);
  out.type.affine = std::make_shared<const Type>(xyz.type);
  out.type.affine_w = static_cast<std::int8_t>(w);
  return out;
}

// transpose(m) and inverse(m) of a map or a normal matrix: the normal matrix of m is
// transpose(inverse(m)); transposing twice, or inverting, keeps what the matrix carries.
std::optional<Value> Checker::map_matrix_call(const std::string& name, const std::vector<Value>& args, SourceRange call_range) {
  if ((name != "transpose" && name != "inverse") || args.size() != 1) return std::nullopt;
  const Type& m = args[0].type;
  if (!is_map(m.geometry) || m.is_array() || m.geometry == Geometry::projmap) return std::nullopt;
  // The table's inverse(map<S, T>) -> map<T, S> is for 4×4 maps; a 3×3 one would match its plain matF there.
  if (name == "inverse" && !m.normal_matrix && m.rows == 4) return std::nullopt;
  Value out;
  out.range = call_range;
  out.type = m;
  std::swap(out.type.from, out.type.to);
  if (name == "transpose") out.type.normal_matrix = !m.normal_matrix;
  return out;
}

// A normal matrix applied to a direction: the map itself carries it; a declared 3×3 normal
// matrix of a rotation is the rotation, which its declaration can say.
std::string Checker::normal_matrix_for_direction_hint(const Value& map, const std::string& kind) const {
  const std::string itself = "apply the map itself to a " + kind;
  const Type& m = map.type;
  if (map.name.empty() || m.rows != 3 || !m.from.is_known() || !m.to.is_known()) return itself;
  return itself + "; if '" + map.name + "' is a rotation, its normal matrix is itself: declare it mat3<" + name_of_space(m.from) +
         ", " + name_of_space(m.to) + ", rigid> " + map.name;
}

// m * v and v * m with a 4×4 map and a vec4, or a 3×3 map and a vec3; nothing when the
// operands are no such pair (the built-in table's map operations then apply).
std::optional<Value> Checker::homogeneous_application(const Value& lhs, const Value& rhs, SourceRange op_range, SourceRange range) {
  const auto square_map = [](const Type& t, int n) {
    return is_map(t.geometry) && t.shape == Shape::matrix && t.rows == n && t.columns == n && !t.is_array();
  };
  const auto vec3 = [](const Type& t) { return t.shape == Shape::vector && t.rows == 3 && t.is_floating() && !t.is_array(); };
  const bool frame = (square_map(lhs.type, 3) && vec3(rhs.type)) || (vec3(lhs.type) && square_map(rhs.type, 3));
  const bool row = frame ? square_map(rhs.type, 3) : (is_vec4(lhs.type) && square_map(rhs.type, 4));
  // h.xyz /= h.w left h's w as it was (divided_in_place): not 1 either.
  const bool stale_w = rhs.w_divided_at && is_vec4(rhs.type);
  if (square_map(lhs.type, 4) && lhs.type.geometry != Geometry::projmap &&
      ((rhs.type.geometry == Geometry::hpoint && rhs.type.shape == Shape::vector && rhs.type.rows == 4 && rhs.type.weight == 1) ||
       stale_w)) {
    // An affine map takes points with w = 1; a projection's output has any w until it is divided.
    const std::string h = operand_text(rhs, "h");
    operand_mismatch("cannot apply " + name_of(lhs.type) + " to " +
                         (stale_w ? "'" + h + "', whose xyz alone were divided by its w" : name_of(rhs.type)) +
                         ": an affine map takes a point as (p, 1.0), and a homogeneous point's w is 1 only once it is divided by it",
                     lhs, rhs, op_range,
                     "divide the whole vec4 by its w first: " + h + " / " + h + ".w (dividing only " + h + ".xyz leaves w as it was)",
                     code::E_KIND_MISMATCH);
    return error_value(range);
  }
  if (!frame && !row && !(square_map(lhs.type, 4) && is_vec4(rhs.type))) return std::nullopt;
  const Value& map = row ? rhs : lhs;
  const Value& v = row ? lhs : rhs;
  const Type& m = map.type;
  Value out;
  out.range = range;
  out.type = Type::vector_of(v.type.scalar, frame ? 3 : 4);
  const Type* carried = frame ? (v.type.geometry == Geometry::none ? nullptr : &v.type) : v.type.affine.get();
  if (!carried) {
    // An unannotated vector under a map: gradual, as plain GLSL (a projmap's result is homogeneous).
    if (m.geometry != Geometry::projmap || row) return out;
    return std::nullopt;  // projmap * vec4: the table's hpoint rule
  }
  const Type& x = *carried;
  const int w = frame ? -1 : v.type.affine_w;  // -1: a 3×3 map, no w
  auto reject = [&](const std::string& message, const std::string& hint, const char* code) {
    operand_mismatch(message, lhs, rhs, op_range, hint, code);
    return std::optional<Value>(error_value(range));
  };
  // The code a hint writes: the program's own operands where they can be quoted.
  const std::string m_name = operand_text(map, "m");
  const std::string kind = geometry_name(x.geometry);
  const bool normal = x.geometry == Geometry::normal;
  // What the matrix carries, and between which spaces, as applied: v * m is transpose(m) * v.
  const bool carries_normals = m.normal_matrix != row;  // transpose(map<A, B>) carries normals from B to A
  const SpaceSlot source = row ? m.to : m.from, target = row ? m.from : m.to;
  const bool rigid = m.geometry == Geometry::rigidmap;
  const std::string applied = std::string(row ? "the transpose of " : "") + name_of(m);
  const std::string cannot = "cannot apply " + applied + " to " + name_of(v.type);
  const std::string row_hint = "v * m multiplies by the transpose of m: a map applies as m * v";

  if (x.geometry == Geometry::point && w == -1)
    return reject(cannot + ": a 3×3 map has no translation, and a point needs one",
                  "apply the 4×4 map to the point, m * vec4(p, 1.0), or to a vector (p - origin)", code::E_KIND_MISMATCH);
  if (x.geometry == Geometry::point && (w == 0 || m.normal_matrix || row))
    return reject(cannot + (w == 0 ? ": a point needs w = 1, and w = 0 drops the map's translation"
                                   : ": a transposed map has no translation to give a point"),
                  w == 0 ? "write vec4(p, 1.0) for a point (w = 0 is for vectors, directions and normals)" : row_hint,
                  code::E_KIND_MISMATCH);
  // A direction given w = 1 under a projection is the point at that offset from the eye: the sky-box idiom.
  const bool sky_box = m.geometry == Geometry::projmap && !row && !normal;
  if (x.geometry != Geometry::point && w == 1 && !sky_box)
    return reject(cannot + ": a " + kind + " needs w = 0, and w = 1 adds the map's translation to it",
                  "write vec4(v, 0.0) for a " + kind + " (w = 1 is for points)", code::E_KIND_MISMATCH);
  // The inverse of the map a normal should go by, without the transpose: the inverse transpose carries
  // normals forward, the inverse alone takes points and vectors backward.
  if (!consistent(x.from, source) && normal && !carries_normals && !row && consistent(x.from, target) && !rigid)
    return reject(cannot + ": this matrix takes values from " + name_of_space(source) + " to " + name_of_space(target) +
                      "; a normal of " + name_of_space(x.from) + " goes by its transpose, the normal matrix transpose(inverse(m))",
                  transposed_argument(m_name).empty()
                      ? "missing transpose: transpose(" + m_name + ") * " + operand_text(v, "n")
                      : "a transpose too many: " + transposed_argument(m_name) +
                            " already is the normal matrix (the inverse transpose): " + transposed_argument(m_name) + " * " +
                            operand_text(v, "n"),
                  code::E_SPACE_MISMATCH);
  if (!consistent(x.from, source))
    return reject(cannot + ": the " + (row ? "transposed " : "") + "map takes values in " + name_of_space(source) + ", not in " +
                      name_of_space(x.from),
                  row ? row_hint : space_hint(source, x.from), code::E_SPACE_MISMATCH);
  if (m.geometry == Geometry::projmap && !row) {
    if (normal) return reject("cannot project " + name_of(v.type) + " with " + name_of(m) + ": a normal is no position", "", code::E_KIND_MISMATCH);
    out.type.geometry = Geometry::hpoint;
    out.type.from = target;
    return out;
  }
  if (carries_normals && !rigid && !normal)
    return reject(cannot + ": the inverse transpose carries normals, not a " + kind,
                  row ? row_hint : normal_matrix_for_direction_hint(map, kind), code::E_KIND_MISMATCH);
  if (normal && !carries_normals && !rigid) {
    const std::string zero = operand_text(v, frame ? "n" : "vec4(n, 0.0)");
    return reject(cannot + ": a normal transforms by the inverse transpose of the map, and this map may scale or shear",
                  "carry it by the inverse transpose: " + zero + " * inverse(" + m_name + "), or transpose(inverse(" + m_name + ")) * " + zero,
                  code::E_KIND_MISMATCH);
  }
  Type moved = x;
  moved.from = target;
  // A normal matrix scales a normal unless its map is rigid: the length is lost until normalize().
  if (normal && carries_normals && !rigid) moved.length_loss = Type::LengthLoss::scaled;
  if (x.geometry == Geometry::direction && !rigid) {
    moved.geometry = Geometry::vector;  // a scaled direction is no longer of unit length
    moved.dim = DimSlot::known(Dimension{});
  }
  if (frame) {
    out.type = moved;
    return out;
  }
  out.type.affine = std::make_shared<const Type>(moved);
  out.type.affine_w = static_cast<std::int8_t>(w);
  return out;
}

// Components of a homogeneous point stored into a stage output leave without their w: the
// perspective divide can no longer happen (a shadow-map coordinate taken as spos.xyz * 0.5 + 0.5).
// The whole vec4 may leave, and so may the divided coordinates.
bool Checker::homogeneous_part_kept(const Value& value, SourceRange target_range, const std::string& target_name) {
  const Type& v = value.type;
  if (v.geometry != Geometry::hpoint || v.shape != Shape::vector || v.rows == 4 || v.weight == 0 || v.is_array()) return true;
  Diagnostic d = Diagnostic::error(value.range, "cannot assign '" + target_name + "' with a value of type " + name_of(v) +
                                                    ": the output keeps these coordinates of the homogeneous point but not the w they are divided by")
                     .with_code(code::E_KIND_MISMATCH);
  if (target_range.valid()) d.with_highlight(target_range);
  add_origin_note(d, value);
  d.with_hint("divide by w before the value leaves the shader (h.xyz / h.w), or pass the whole vec4 and divide where it is used");
  report(std::move(d));
  return false;
}

std::string Checker::operand_text(const Value& v, const std::string& fallback) const {
  if (!v.name.empty()) return v.name;
  const SourceRange& r = v.range;
  if (options_.sources == nullptr || !r.valid() || r.begin.file != r.end.file || r.end.offset < r.begin.offset) return fallback;
  const std::string_view file = options_.sources->text(r.begin.file);
  if (r.end.offset > file.size() || r.end.offset - r.begin.offset > 60) return fallback;
  const std::string_view text = file.substr(r.begin.offset, r.end.offset - r.begin.offset);
  return text.find_first_of("\n\r") == std::string_view::npos ? std::string(text) : fallback;
}

// mat3(m) of a 4×4 map is its linear part; mat3(t, b, n) of three unit vectors of one space is
// the frame from the unnamed space of its coordinates to that space (a TBN basis); nothing for
// any other matrix constructor.
std::optional<Type> Checker::frame_constructor(const Type& target, const std::vector<Value>& args) const {
  if (target.shape != Shape::matrix || target.rows != 3 || target.columns != 3) return std::nullopt;
  if (args.size() == 1) {
    const Type& m = args[0].type;
    if (!is_map(m.geometry) || m.geometry == Geometry::projmap || m.is_array() || m.rows != 4) return std::nullopt;
    Type linear = m;
    linear.rows = linear.columns = 3;
    linear.scalar = target.scalar;
    return linear;
  }
  if (args.size() != 3) return std::nullopt;
  SpaceSlot space;
  bool unit = true;
  for (const Value& a : args) {
    const Type& c = a.type;
    if (c.shape != Shape::vector || c.rows != 3 || c.is_array()) return std::nullopt;
    // A plain vec3 column (a tangent from an unannotated attribute, cross(n, vec3(0.0, 0.0, 1.0))) is
    // gradual: it is taken to be an axis of the space the other columns are in.
    const bool plain = c.geometry == Geometry::none && c.from.state == SpaceSlot::State::unknown &&
                       (c.dim.state == DimSlot::State::unknown || (c.dim.is_known() && c.dim.value.is_dimensionless()));
    if (plain) continue;
    if (!vectorish(c.geometry) || c.from.state != SpaceSlot::State::known) return std::nullopt;
    if (space.state == SpaceSlot::State::known && !(space == c.from)) return std::nullopt;
    space = c.from;
    unit = unit && c.geometry != Geometry::vector;
  }
  if (space.state != SpaceSlot::State::known) return std::nullopt;
  Type frame = target.plain();
  frame.geometry = unit ? Geometry::rigidmap : Geometry::map;
  frame.to = space;
  return frame;
}

}  // namespace safegi::detail

namespace safegi::detail {

namespace {

// `h.<member>` of a variable h: its name, else empty.
std::string member_of_variable(const ast::Expr* e, std::string_view member) {
  const auto* m = ast::dyn_cast<ast::MemberExpr>(e);
  const auto* id = m ? ast::dyn_cast<ast::IdentifierExpr>(m->base) : nullptr;
  return id && m->member == member ? id->name : std::string();
}

}  // namespace

bool Checker::homogeneous_parameters(const std::string& callee, const std::vector<Type>& params, const std::vector<Value>& args) {
  // `project(h.xy, h.w)`: a w handed over beside its coordinates lets the function divide.
  const auto w_given = [&](const Type& coordinates) {
    return std::any_of(args.begin(), args.end(), [&](const Value& v) {
      return v.homogeneous_w && v.type.weight == coordinates.weight && consistent(v.type.from, coordinates.from);
    });
  };
  for (std::size_t i = 0; i < args.size() && i < params.size(); ++i) {
    const Type& a = args[i].type;
    const std::string argument = "argument " + std::to_string(i + 1) + " of '" + callee + "'";
    if (params[i].geometry == Geometry::hpoint && args[i].w_divided_at && a.shape == Shape::vector && a.rows == 4) {
      Diagnostic d = Diagnostic::error(args[i].range, argument + " is '" + written_name(args[i]) +
                                                          "', whose xyz were divided by its w: it is no longer the homogeneous point '" +
                                                          callee + "' takes")
                         .with_code(code::E_KIND_MISMATCH);
      d.with_note(Diagnostic::note(*args[i].w_divided_at, "divided here"));
      d.with_hint("divide by w in one place: pass the vec4 as the projection made it, or take the divided coordinates");
      report(std::move(d));
      return false;
    }
    if (params[i].geometry != Geometry::hpoint && a.geometry == Geometry::hpoint && a.shape == Shape::vector && a.rows < 4 &&
        a.weight != 0 && !a.is_array() && !w_given(a)) {
      Diagnostic d = Diagnostic::error(args[i].range, argument + " has type " + name_of(a) +
                                                          ": the parameter takes these coordinates of the homogeneous point but not the w they are divided by")
                         .with_code(code::E_KIND_MISMATCH);
      add_origin_note(d, args[i]);
      d.with_hint("divide by w first (h.xy / h.w), or pass the whole vec4 and divide where it is used");
      report(std::move(d));
      return false;
    }
  }
  return true;
}

// normalize(h.xyz), length(h.xyz), dFdx(h.xyz) of a homogeneous point before its divide: its
// coordinates are a position only once divided by w (a ray's direction from the inverse projection's
// undivided xyz, a tangent frame from derivatives of clip coordinates).
bool Checker::homogeneous_arguments(const std::string& name, const std::vector<Value>& args) {
  if (!builtin_argument_rule(name, ArgumentRule::divided_only)) return true;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const Type& a = args[i].type;
    if (a.geometry != Geometry::hpoint || a.shape != Shape::vector || a.rows == 4 || a.weight == 0 || a.is_array()) continue;
    const std::string text = written_name(args[i]);
    const std::size_t dot = text.rfind('.');
    const bool swizzle = dot != std::string::npos && dot > 0 && text.find_first_of("()[] ") == std::string::npos;
    Diagnostic d = Diagnostic::error(args[i].range, "argument " + std::to_string(i + 1) + " of '" + name + "' has type " + name_of(a) +
                                                        ": the coordinates of a homogeneous point are a position in " + name_of_space(a.from) +
                                                        " only once divided by its w")
                       .with_code(code::E_KIND_MISMATCH);
    add_origin_note(d, args[i]);
    const bool derivative = name.starts_with("dF") || name.starts_with("fwidth");
    const std::string quotient = swizzle ? text + " / " + text.substr(0, dot) + ".w" : std::string("h.xyz / h.w");
    const std::string divided = swizzle && args.size() == 1 ? name + "(" + quotient + ")" : quotient;
    d.with_hint(derivative ? "differentiate a position of a space (the view-space one, say), or divide by w first: " + divided
                           : "divide by w first: " + divided);
    report(std::move(d));
    return false;
  }
  return true;
}

void Checker::divided_in_place(const ast::AssignExpr& e) {
  const auto* target = ast::dyn_cast<ast::MemberExpr>(e.lhs);
  const auto* id = target ? ast::dyn_cast<ast::IdentifierExpr>(target->base) : nullptr;
  if (id == nullptr || target->member.find_first_of("wq") != std::string::npos || target->member.size() < 2) return;
  bool by_own_w = false;
  if (e.op == ast::AssignOp::Div) {
    by_own_w = member_of_variable(e.rhs, "w") == id->name;
  } else if (e.op == ast::AssignOp::Assign) {
    const auto* quotient = ast::dyn_cast<ast::BinaryExpr>(e.rhs);
    by_own_w = quotient && quotient->op == ast::BinaryOp::Div && member_of_variable(quotient->rhs, "w") == id->name &&
               member_of_variable(quotient->lhs, target->member) == id->name;
  }
  if (!by_own_w) return;
  for (auto scope = scopes_.rbegin(); scope != scopes_.rend(); ++scope)
    if (auto found = scope->find(id->name); found != scope->end()) {
      Variable& h = found->second;
      if (h.type.geometry != Geometry::hpoint || h.type.shape != Shape::vector || h.type.rows != 4 || h.type.is_array()) return;
      h.type = Type::vector_of(h.type.scalar, 4);  // coordinates and a stale w: plain from here on
      h.w_divided_at = e.range;
      return;
    }
}

}  // namespace safegi::detail
