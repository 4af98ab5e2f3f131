// Binary operators: GLSL's shape rules, then dimensions (Abelian group) and
// the affine rules of points, vectors, directions and normals.

#include <climits>
#include <cstdint>
#include <vector>

#include <safegi/parser/printer.hpp>

#include "checker_impl.hpp"
#include "dim_slot.hpp"

namespace safegi::detail {
namespace {

// A spectrum or a kind-less value: what colour arithmetic takes (no point, vector or map).
bool colour_like(Geometry g) { return g == Geometry::spectrum || g == Geometry::none; }

// A normal, or a vector that is a plain multiple of one (Type::normal_multiple).
bool normal_like(const Type& t) {
  return t.geometry == Geometry::normal || (t.geometry == Geometry::vector && t.normal_multiple);
}

// `n * 0.5 + 0.5`, `0.5 + 0.5 * d`, `n + 1.0`: a plain (unit or halved) vector's coordinates
// moved by the literal 0.5 or 1 into [0, 1], the way normals are written as colours.
bool unit_interval_encoding(const Type& geo, const Value& number) {
  const bool vector_kind = geo.geometry == Geometry::direction || geo.geometry == Geometry::normal || geo.geometry == Geometry::vector;
  return vector_kind && geo.dim.is_known() && geo.dim.value.is_dimensionless() && number.literal && number.number &&
         (*number.number == 0.5 || *number.number == 1.0);
}

bool is_arith(ast::BinaryOp op) {
  return op == ast::BinaryOp::Add || op == ast::BinaryOp::Sub || op == ast::BinaryOp::Mul || op == ast::BinaryOp::Div;
}

const char* verb(ast::BinaryOp op) {
  switch (op) {
    case ast::BinaryOp::Add: return "add";
    case ast::BinaryOp::Sub: return "subtract";
    case ast::BinaryOp::Mul: return "multiply";
    case ast::BinaryOp::Div: return "divide";
    case ast::BinaryOp::Mod: return "take the remainder of";
    default: return "compare";
  }
}

// GLSL's result shape of an arithmetic operator, or nothing when the operands do not fit.
std::optional<Type> arithmetic_shape(ast::BinaryOp op, const Type& a, const Type& b) {
  if (a.is_array() || b.is_array() || !a.is_numeric() || !b.is_numeric()) return std::nullopt;
  const std::optional<Scalar> common = common_scalar(a.scalar, b.scalar);
  if (!common) return std::nullopt;
  const Scalar scalar = *common;
  if (op == ast::BinaryOp::Mod && (a.is_floating() || b.is_floating())) return std::nullopt;
  auto with = [&](Type t) {
    t.scalar = scalar;
    return t.plain();
  };
  if (a.shape == Shape::scalar) return with(b);
  if (b.shape == Shape::scalar) return with(a);
  if (a.shape == Shape::vector && b.shape == Shape::vector) {
    if (a.rows != b.rows) return std::nullopt;
    return with(a);
  }
  if (a.shape == Shape::matrix && b.shape == Shape::matrix) {
    if (op == ast::BinaryOp::Mul) {
      if (a.columns != b.rows) return std::nullopt;
      return Type::matrix_of(scalar, b.columns, a.rows);
    }
    if (a.columns != b.columns || a.rows != b.rows) return std::nullopt;
    return with(a);
  }
  if (op != ast::BinaryOp::Mul) return std::nullopt;
  if (a.shape == Shape::matrix && b.shape == Shape::vector) {
    if (a.columns != b.rows) return std::nullopt;
    return Type::vector_of(scalar, a.rows);
  }
  if (a.shape == Shape::vector && b.shape == Shape::matrix) {
    if (a.rows != b.rows) return std::nullopt;
    return Type::vector_of(scalar, b.columns);
  }
  return std::nullopt;
}

}  // namespace

void Checker::operand_mismatch(const std::string& message, const Value& lhs, const Value& rhs, SourceRange op_range,
                               const std::string& hint, const char* code) {
  Diagnostic d = Diagnostic::error(op_range, message).with_code(code).with_highlight(lhs.range).with_highlight(rhs.range);
  add_origin_note(d, lhs);
  add_origin_note(d, rhs);
  if (!hint.empty()) d.with_hint(hint);
  report(std::move(d));
}

// A left-deep chain (a + b + c + …, the parser accepts 2048 operators) is
// walked along its left spine in one frame: recursing once per operator
// overflowed the stack (≈1.5 KB a level in Release, ≈8 KB under ASan).
// Operands are still checked left to right and every node is recorded.
Value Checker::binary(const ast::BinaryExpr& e) {
  std::vector<const ast::BinaryExpr*> spine{&e};
  while (spine.back()->lhs && spine.back()->lhs->kind == ast::NodeKind::BinaryExpr)
    spine.push_back(static_cast<const ast::BinaryExpr*>(spine.back()->lhs));
  Value value = expr(spine.back()->lhs);
  for (auto it = spine.rbegin(); it != spine.rend(); ++it) {
    const ast::BinaryExpr& node = **it;
    Value rhs = expr(node.rhs);
    const Value lhs = std::move(value);
    value = arithmetic(&node, node.op, lhs, rhs, node.op_range, node.range);
    if (!carry_pi_factor(node.op, lhs, rhs, value, node.op_range)) value = error_value(node.range);
    carry_inverse_squares(node, lhs, rhs, value);
    if (node.op == ast::BinaryOp::Sub && it == spine.rbegin() && !value.type.is_error()) gram_schmidt(node, value);
    // Only the leftmost operand is a variable as written: `L / d`, not `a * L / d`.
    if (node.op == ast::BinaryOp::Div && it == spine.rbegin() && !value.type.is_error())
      if (std::optional<Value> unit = divided_by_own_length(node.lhs, lhs, rhs, node.range)) value = *unit;
    if (&node != &e) value = record(&node, std::move(value));  // expr() records the outermost
  }
  return value;
}

bool Checker::buffer_reference2(SourceRange where, const std::string& what) {
  const LanguageLevel* level = language();
  if (!level || level->extension_enabled("GL_EXT_buffer_reference2")) return true;
  reject(where, what + " requires GL_EXT_buffer_reference2", code::E_VERSION, "enable it with '#extension GL_EXT_buffer_reference2 : enable'");
  return false;
}

// GL_EXT_buffer_reference2: a reference plus or minus an integer is the reference that many blocks
// on (glslang steps by the block's size rounded to its buffer_reference_align); two references of
// one type subtract to the int64_t count of blocks between them. Nothing else applies to a reference
// but `,`, `==` and `!=` (and those are the switch's).
std::optional<Value> Checker::reference_arithmetic(ast::BinaryOp op, const Value& lhs, const Value& rhs, SourceRange op_range,
                                                   SourceRange range) {
  const auto reference = [](const Type& t) {
    return t.shape == Shape::structure && t.structure && t.structure->buffer_reference && !t.is_array();
  };
  const Type& a = lhs.type;
  const Type& b = rhs.type;
  if (!reference(a) && !reference(b)) return std::nullopt;
  if (op != ast::BinaryOp::Add && op != ast::BinaryOp::Sub) return std::nullopt;
  const auto integer = [](const Type& t) { return t.shape == Shape::scalar && t.is_integer() && !t.is_array(); };
  Value out;
  out.range = range;
  const auto stride = [&](const Type& t) -> std::optional<long long> {
    auto it = reference_strides_.find(t.structure);
    return it == reference_strides_.end() ? std::nullopt : std::optional<long long>(it->second);
  };
  if (reference(a) && reference(b) && op == ast::BinaryOp::Sub && a.structure == b.structure) {
    out.type = Type::scalar_of(Scalar::int64_);
    if (lhs.constant && rhs.constant && stride(a)) out.constant = (*lhs.constant - *rhs.constant) / *stride(a);
  } else if ((reference(a) && integer(b)) || (op == ast::BinaryOp::Add && integer(a) && reference(b))) {
    const Type& r = reference(a) ? a : b;
    out.type = r;
    // The address of T(uint64_t(0)) + 1 is a constant: the #define sizeof(T) of glslang's tests.
    if (lhs.constant && rhs.constant && stride(r)) {
      const long long steps = reference(a) ? *rhs.constant : *lhs.constant;
      const long long address = reference(a) ? *lhs.constant : *rhs.constant;
      out.constant = address + (op == ast::BinaryOp::Sub ? -steps : steps) * *stride(r);
    }
  } else {
    operand_mismatch("invalid operands to binary expression (" + name_of(a) + " and " + name_of(b) +
                         "): a buffer reference moves by an integer, and two of one type subtract",
                     lhs, rhs, op_range, "", code::E_INVALID_OPERANDS);
    return error_value(range);
  }
  if (!buffer_reference2(op_range, "arithmetic on a buffer reference")) return error_value(range);
  return out;
}

Value Checker::arithmetic(const ast::Node* node, ast::BinaryOp op, const Value& lhs, const Value& rhs,
                          SourceRange op_range, SourceRange range) {
  if (lhs.type.is_error() || rhs.type.is_error()) return error_value(range);
  const Type& a = lhs.type;
  const Type& b = rhs.type;
  Value out;
  out.range = range;
  auto invalid = [&]() {
    operand_mismatch("invalid operands to binary expression (" + name_of(a) + " and " + name_of(b) + ")", lhs, rhs,
                     op_range, "", code::E_INVALID_OPERANDS);
    return error_value(range);
  };
  if (std::optional<Value> v = reference_arithmetic(op, lhs, rhs, op_range, range)) return *v;
  switch (op) {
    case ast::BinaryOp::Comma: return rhs;
    case ast::BinaryOp::LogAnd:
    case ast::BinaryOp::LogOr:
    case ast::BinaryOp::LogXor: {
      const Type boolean = Type::scalar_of(Scalar::bool_);
      if (!same_glsl_type(a.plain(), boolean) || !same_glsl_type(b.plain(), boolean)) return invalid();
      out.type = boolean;
      return out;
    }
    case ast::BinaryOp::Lt:
    case ast::BinaryOp::Gt:
    case ast::BinaryOp::Le:
    case ast::BinaryOp::Ge:
    case ast::BinaryOp::Eq:
    case ast::BinaryOp::Ne: {
      const bool ordering = op != ast::BinaryOp::Eq && op != ast::BinaryOp::Ne;
      Type pa = a, pb = b;
      if (const std::optional<Scalar> common = common_scalar(pa.scalar, pb.scalar)) pa.scalar = pb.scalar = *common;
      if (!same_glsl_type(pa.plain(), pb.plain())) return invalid();
      if (ordering && !(a.shape == Shape::scalar && a.is_numeric() && !a.is_array())) return invalid();
      if (!ordering && (a.shape == Shape::opaque || a.shape == Shape::void_)) return invalid();
      // Comparisons need equal dimensions; a zero literal compares with anything.
      const DimSlot da = value_dimension(a, result_.registry), db = value_dimension(b, result_.registry);
      if (!lhs.zero && !rhs.zero && !consistent(da, db) && !cosine_as_number(da, db) && !cosine_as_number(db, da)) {
        operand_mismatch("cannot compare " + name_of(a) + " and " + name_of(b), lhs, rhs, op_range,
                         unnormalized_dot_hint(lhs).value_or(unnormalized_dot_hint(rhs).value_or(physics_hint(da, db))),
                         code::E_DIMENSION_MISMATCH);
        return error_value(range);
      }
      // `projCoords.z > stored` before the divide compares z·w, not a depth.
      if ((a.geometry == Geometry::hpoint) != (b.geometry == Geometry::hpoint) && !lhs.zero && !rhs.zero) {
        operand_mismatch("cannot compare " + name_of(a) + " and " + name_of(b) +
                             ": a homogeneous coordinate is a position only after the divide by w",
                         lhs, rhs, op_range, "divide by w first (h.z / h.w), or compare homogeneous values of the same w",
                         code::E_KIND_MISMATCH);
        return error_value(range);
      }
      if (!consistent(a.from, b.from)) {
        operand_mismatch("cannot compare " + name_of(a) + " and " + name_of(b) + ": they are in different spaces", lhs, rhs,
                         op_range, space_hint(a.from, b.from), code::E_SPACE_MISMATCH);
        return error_value(range);
      }
      out.type = Type::scalar_of(Scalar::bool_);
      return out;
    }
    case ast::BinaryOp::BitAnd:
    case ast::BinaryOp::BitXor:
    case ast::BinaryOp::BitOr:
    case ast::BinaryOp::Shl:
    case ast::BinaryOp::Shr: {
      if (!a.is_integer() || !b.is_integer() || a.is_array() || b.is_array() || a.shape == Shape::matrix ||
          b.shape == Shape::matrix)
        return invalid();
      const bool shift = op == ast::BinaryOp::Shl || op == ast::BinaryOp::Shr;
      if (!shift && a.shape == Shape::vector && b.shape == Shape::vector && a.rows != b.rows) return invalid();
      if (shift && a.shape == Shape::scalar && b.shape == Shape::vector) return invalid();
      out.type = (shift || a.shape == Shape::vector) ? a.plain() : b.plain();
      if (!shift && a.scalar != b.scalar) {
        const std::optional<Scalar> common = common_scalar(a.scalar, b.scalar);
        if (!common) return invalid();
        out.type.scalar = *common;
      }
      if (lhs.constant && rhs.constant) {
        const long long x = *lhs.constant, y = *rhs.constant;
        if (op == ast::BinaryOp::BitAnd) out.constant = x & y;
        if (op == ast::BinaryOp::BitOr) out.constant = x | y;
        if (op == ast::BinaryOp::BitXor) out.constant = x ^ y;
        if (shift && y >= 0 && y < 32)
          out.constant = op == ast::BinaryOp::Shl ? static_cast<long long>((static_cast<unsigned long long>(x) << y) & 0xffffffffull) : x >> y;
      }
      return out;
    }
    default: break;
  }

  // + - * / %
  if (!unit_length_offset(op, lhs, rhs)) return error_value(range);
  if (std::optional<Value> v = affine_sum(op, lhs, rhs, op_range, range)) return *v;
  std::optional<Type> shape = arithmetic_shape(op, a, b);
  const bool map_operand = is_map(a.geometry) || is_map(b.geometry);
  if (map_operand && op == ast::BinaryOp::Mul) {
    if (std::optional<Value> v = homogeneous_application(lhs, rhs, op_range, range)) return *v;
    const bool composing = b.shape == Shape::matrix;
    if (composing && a.rows == 3 && a.columns == 3 && b.rows == 3 && b.columns == 3 && is_map(a.geometry) && is_map(b.geometry))
      return compose_3x3(lhs, rhs, op_range, range);
    if (a.normal_matrix || b.normal_matrix) {
      // Normal matrices compose with normal matrices: transpose(inverse(m2 * m1)) = N(m2) * N(m1); a
      // rotation is its own normal matrix (N(R) = R), so it composes with one too.
      const auto normal_or_rigid = [](const Type& t) { return t.normal_matrix || t.geometry == Geometry::rigidmap; };
      if (!(normal_or_rigid(a) && normal_or_rigid(b)) || !composing) {
        operand_mismatch("invalid operands to binary expression (" + name_of(a) + " and " + name_of(b) + ")", lhs, rhs, op_range,
                         "a normal matrix carries normals as vec4(n, 0.0), and composes only with normal matrices",
                         code::E_INVALID_OPERANDS);
        return error_value(range);
      }
      Value l = lhs, r = rhs;
      l.type.normal_matrix = r.type.normal_matrix = false;
      if (l.type.geometry == Geometry::rigidmap) l.type.geometry = Geometry::map;  // the product carries normals only
      if (r.type.geometry == Geometry::rigidmap) r.type.geometry = Geometry::map;
      std::optional<Value> v = geometric_operator(nullptr, "compose", l, r, range);
      if (!v) return error_value(range);
      v->type.normal_matrix = true;
      return *v;
    }
    // `m * x` and `m2 * m1` are the map operations of the built-in table.
    std::optional<Value> v = geometric_operator(node, composing ? "compose" : "transform", lhs, rhs, range);
    if (v) return *v;
    return error_value(range);
  }
  if (!shape) return invalid();
  if (a.geometry != Geometry::none || b.geometry != Geometry::none) {
    if (is_arith(op)) return geometric_arithmetic(op, lhs, rhs, *shape, op_range, range);
  }

  const DimSlot da = value_dimension(a, result_.registry), db = value_dimension(b, result_.registry);
  out.type = *shape;
  if (op == ast::BinaryOp::Add || op == ast::BinaryOp::Sub || op == ast::BinaryOp::Mod) {
    const bool cosine_a = cosine_as_number(db, da), cosine_b = cosine_as_number(da, db);  // 1 - cos θ is a number
    if (!lhs.zero && !rhs.zero && !consistent(da, db) && !cosine_a && !cosine_b) {
      operand_mismatch(std::string("cannot ") + verb(op) + " " + name_of(a) + " and " + name_of(b), lhs, rhs, op_range,
                       unnormalized_dot_hint(lhs).value_or(unnormalized_dot_hint(rhs).value_or(angle_fraction_hint(lhs, rhs).value_or(
                           literal_sum_hint(lhs, rhs).value_or(operand_hint(da, db, rhs.range))))),
                       code::E_DIMENSION_MISMATCH);
      return error_value(range);
    }
    if (da.state == DimSlot::State::unknown || db.state == DimSlot::State::unknown) out.type.dim = DimSlot::unknown();
    else if (!lhs.zero && !rhs.zero && (cosine_a || cosine_b)) out.type.dim = cosine_a ? db : da;
    else out.type.dim = lhs.zero ? db : da;
    keep_shared_spelling(out.type.dim, {da, db});  // k + k keeps k's name
    out.zero = lhs.zero && rhs.zero;
  } else {
    std::optional<DimSlot> d = combine(da, db, op == ast::BinaryOp::Mul ? 1 : -1);
    if (!d) {
      operand_mismatch("dimension exponent overflows in this product", lhs, rhs, op_range, "", code::E_DIMENSION_OVERFLOW);
      return error_value(range);
    }
    out.type.dim = *d;
    keep_scaled_spelling(out.type.dim, da, db, op == ast::BinaryOp::Div);
    if (op == ast::BinaryOp::Mul)
      if (std::optional<DimSlot> reference = conversion_written_out(lhs, da, rhs, db)) out.type.dim = *reference;
    out.zero = op == ast::BinaryOp::Mul && (lhs.zero || rhs.zero);
    if (out.zero) out.type.dim = DimSlot::zero();
  }
  if (lhs.constant && rhs.constant && out.type.shape == Shape::scalar && out.type.is_integer()) {
    // Wrapping, as the 64-bit types (INT64_MIN / -1L) do not fit the folding otherwise; a result
    // beyond 32 bits is not folded.
    const long long x = *lhs.constant, y = *rhs.constant;
    const auto ux = static_cast<unsigned long long>(x), uy = static_cast<unsigned long long>(y);
    if (op == ast::BinaryOp::Add) out.constant = static_cast<long long>(ux + uy);
    if (op == ast::BinaryOp::Sub) out.constant = static_cast<long long>(ux - uy);
    if (op == ast::BinaryOp::Mul) out.constant = static_cast<long long>(ux * uy);
    if ((op == ast::BinaryOp::Div || op == ast::BinaryOp::Mod) && y != 0 && !(y == -1 && x == LLONG_MIN))
      out.constant = op == ast::BinaryOp::Div ? x / y : x % y;
    if (out.constant && (*out.constant > 0xffffffffll || *out.constant < -0x80000000ll)) out.constant.reset();
  }
  if (out.constant) out.number = static_cast<double>(*out.constant);
  // 2.0 * PI * u, x * PI / 180.0: a multiple of π scaled by plain numbers is an angle in radians.
  const auto plain = [&](const Value& v, const DimSlot& d) { return v.type.shape == Shape::scalar && d.is_known() && d.value.is_dimensionless(); };
  if ((op == ast::BinaryOp::Mul || op == ast::BinaryOp::Div) && plain(lhs, da) && plain(rhs, db))
    out.pi_multiple = op == ast::BinaryOp::Mul ? lhs.pi_multiple != rhs.pi_multiple : lhs.pi_multiple && !rhs.pi_multiple;
  // Float constants fold too (pow's exponent `n + 1.0`, `int(N * 0.5)` array sizes).
  if (lhs.number && rhs.number && out.type.shape == Shape::scalar && out.type.is_floating()) {
    const double x = *lhs.number, y = *rhs.number;
    if (op == ast::BinaryOp::Add) out.number = x + y;
    if (op == ast::BinaryOp::Sub) out.number = x - y;
    if (op == ast::BinaryOp::Mul) out.number = x * y;
    if (op == ast::BinaryOp::Div && y != 0.0) out.number = x / y;
  }
  return out;
}

// A "cosine" that is a dot product with a vector of some length (`dot(-s, l)` where the spot
// axis s was not normalised): the hint names the vector to normalise.
std::optional<std::string> Checker::unnormalized_dot_hint(const Value& v) const {
  const ast::Expr* e = expression_at(v.origin && v.origin->inferred ? v.origin->range : v.range);
  const ast::CallExpr* call = nullptr;
  for (;;) {  // through parentheses and the usual guards: abs(dot(n, v)), max(dot(n, v), 0.0)
    while (e != nullptr && ast::isa<ast::ParenExpr>(e)) e = static_cast<const ast::ParenExpr*>(e)->inner;
    call = e ? ast::dyn_cast<ast::CallExpr>(e) : nullptr;
    if (call == nullptr || call->args.empty() ||
        (call->callee != "abs" && call->callee != "max" && call->callee != "min" && call->callee != "clamp"))
      break;
    e = call->args[0];
  }
  if (call == nullptr || call->callee != "dot" || call->args.size() != 2) return std::nullopt;
  for (const ast::Expr* arg : call->args) {
    const auto type = result_.types.find(arg);
    if (type == result_.types.end() || type->second.geometry != Geometry::vector) continue;
    const DimSlot d = value_dimension(type->second, result_.registry);
    if (!d.is_known() || d.value.is_dimensionless()) continue;
    const std::string text = print_expression(*arg);
    return "a cosine is the dot product of unit vectors, and " + text + " is a vector of " + result_.registry.format(d.value) +
           ": normalize(" + text + ")";
  }
  return std::nullopt;
}

// A number added to a quantity (`1.0 + d * d`, a regularised falloff) means that number of
// some unit: the sum changes with the unit the rest is in, so the number needs its unit.
std::optional<std::string> Checker::literal_sum_hint(const Value& lhs, const Value& rhs) const {
  const Value* number = lhs.literal && !lhs.zero ? &lhs : rhs.literal && !rhs.zero ? &rhs : nullptr;
  const Value* quantity = number == &lhs ? &rhs : &lhs;
  if (number == nullptr || quantity->literal) return std::nullopt;
  const DimensionRegistry& reg = result_.registry;
  const DimSlot d = value_dimension(quantity->type, reg);
  if (!d.is_known() || d.value.is_dimensionless() || reg.has_unit_factors(d.value)) return std::nullopt;
  for (const Unit& unit : reg.units())
    if (unit.dimension == d.value && DimensionRegistry::same_scale(unit.scale, 1.0))
      return "a plain number beside " + reg.format(d.value) + " means that many of some unit: the sum would change with the unit; give it "
             "its unit, " + operand_text(*number, "x") + " * " + unit.name;
  return "a plain number beside " + reg.format(d.value) + " means that many of some unit: give it the dimension " + reg.format(d.value);
}

Value Checker::geometric_arithmetic(ast::BinaryOp op, const Value& lhs, const Value& rhs, Type shape,
                                    SourceRange op_range, SourceRange range) {
  const Type& a = lhs.type;
  const Type& b = rhs.type;
  const Geometry ga = a.geometry, gb = b.geometry;
  const DimSlot da = value_dimension(a, result_.registry), db = value_dimension(b, result_.registry);
  Value out;
  out.range = range;
  out.type = shape;
  auto reject = [&](const std::string& message, const std::string& hint, const char* code) {
    operand_mismatch(message, lhs, rhs, op_range, hint, code);
    return error_value(range);
  };
  const std::string both = name_of(a) + " and " + name_of(b);
  const SpaceSlot space = a.from.state != SpaceSlot::State::unknown ? a.from : b.from;

  if (op == ast::BinaryOp::Add || op == ast::BinaryOp::Sub) {
    const bool add = op == ast::BinaryOp::Add;
    if (!add && !written_reflection_ok(lhs, rhs, op_range)) return error_value(range);
    if (ga == Geometry::point && gb == Geometry::point && add)
      return reject("cannot add two points (" + both + ")", "subtract them to get a vector, or average them with mix(p, q, 0.5)",
                    code::E_POINT_ARITHMETIC);
    // A number added to every coordinate of a point or vector moves it along
    // (1, 1, 1), which depends on the axes: `t - dot(t, n)` meant `t - dot(t, n) * n`.
    const bool scalar_a = a.shape == Shape::scalar, scalar_b = b.shape == Shape::scalar;
    auto spatial = [](Geometry g) { return g == Geometry::point || vectorish(g); };
    if ((spatial(ga) && scalar_b && !rhs.zero) || (spatial(gb) && scalar_a && !lhs.zero)) {
      const Type& geo = spatial(ga) ? a : b;
      if (unit_interval_encoding(geo, spatial(ga) ? rhs : lhs)) {
        // n * 0.5 + 0.5, d + 1.0: a unit vector's coordinates remapped to [0, 1] (a normal written
        // as a colour): plain numbers, no longer a vector of the space.
        out.type.dim = DimSlot::known(Dimension{});
        return out;
      }
      return reject(std::string("cannot ") + verb(op) + " " + both + ": a number added to every coordinate of a " +
                        geometry_name(geo.geometry) + " depends on the axes of " + name_of_space(geo.from),
                    "scale a direction by it instead (e.g. t - dot(t, n) * n), or build the vector it stands for",
                    code::E_KIND_MISMATCH);
    }
    // A kind-less vec3 may be a point (gradual typing): plain - point is a vector.
    if (gb == Geometry::point && ga != Geometry::point && ga != Geometry::none && !add)
      return reject("cannot subtract a point from " + name_of(a), "only point - point and point - vector are defined",
                    code::E_POINT_ARITHMETIC);
    if (!consistent(a.from, b.from))
      return reject(std::string("cannot ") + verb(op) + " " + both + ": they are in different spaces",
                    ga == Geometry::hpoint && gb == Geometry::hpoint
                        ? "divide each by its own w first (h.xy / h.w): two projections' coordinates meet only after the perspective divide"
                        : space_hint(a.from, b.from),
                    code::E_SPACE_MISMATCH);
    // hpoint<S> ± vec4(v, 0.0) of a vector of another space: an offset added in the wrong space.
    for (const auto& [h, other] : {std::pair{&a, &b}, std::pair{&b, &a}})
      if (h->geometry == Geometry::hpoint && other->affine && other->affine->from.is_known() && !consistent(h->from, other->affine->from))
        return reject(std::string("cannot ") + verb(op) + " " + both + ": they are in different spaces",
                      "add the offset in " + name_of_space(other->affine->from) + ", before the map to " + name_of_space(h->from) +
                          " (m * (p + vec4(v, 0.0)))",
                      code::E_SPACE_MISMATCH);
    // Colours as numbers, as scalars are: a plain colour times a cosine (a Lambert term of
    // unannotated lights) beside one times a lobe (Phong's specular) is a plain colour.
    const bool colours = colour_like(ga) && colour_like(gb);
    const bool cosine_a = colours && cosine_as_number(db, da), cosine_b = colours && cosine_as_number(da, db);
    if (!lhs.zero && !rhs.zero && !consistent(da, db) && !cosine_a && !cosine_b)
      return reject(std::string("cannot ") + verb(op) + " " + both, unit_vector_sum_hint(lhs, rhs, da, db), code::E_DIMENSION_MISMATCH);
    const bool unknown = da.state == DimSlot::State::unknown || db.state == DimSlot::State::unknown;
    out.type.dim = unknown ? DimSlot::unknown() : (cosine_a ? db : cosine_b ? da : lhs.zero ? db : da);
    keep_shared_spelling(out.type.dim, {da, db});
    out.type.from = space;
    if (gb == Geometry::point && !add && (ga == Geometry::point || ga == Geometry::none)) {
      out.type.geometry = Geometry::vector;  // point - point
      out.type.orientation = point_difference_orientation(a, b);
    } else if (ga == Geometry::point || gb == Geometry::point) {
      out.type.geometry = Geometry::point;   // point ± displacement: an offset shaded point is still the shaded one
      out.type.orientation = (ga == Geometry::point ? a : b).orientation;
    } else if (ga == Geometry::spectrum || gb == Geometry::spectrum) {
      out.type.geometry = colour_like(ga) && colour_like(gb) ? Geometry::spectrum : Geometry::none;
      out.type.from = SpaceSlot::unknown();
    } else if (ga == Geometry::hpoint || gb == Geometry::hpoint) {
      out.type.geometry = Geometry::hpoint;
      out.type.dim = DimSlot::unknown();
      out.type.weight = ga == Geometry::hpoint ? a.weight : b.weight;
    } else if (normal_like(a) && normal_like(b)) {
      // Normals are covectors: n + m and w0 * n0 + w1 * n1 are normals of the space (unit only once
      // normalized); m - n is a normal's change, a vector a normal plus it is a normal again.
      out.type = ga == Geometry::normal ? a : b;
      out.type.dim = DimSlot::known(Dimension{});
      out.type.orientation = sum_orientation(add, a.orientation, b.orientation);
      if (add) {
        out.type.geometry = Geometry::normal;
        out.type.length_loss = Type::LengthLoss::blended;
        out.type.normal_multiple = false;
      } else {
        out.type.geometry = Geometry::vector;
        out.type.length_loss = Type::LengthLoss::none;
        out.type.normal_multiple = true;
      }
    } else if ((ga == Geometry::normal && gb == Geometry::none && db.state == DimSlot::State::unknown) ||
               (gb == Geometry::normal && ga == Geometry::none && da.state == DimSlot::State::unknown)) {
      // A normal offset by an unannotated vector (a morph target's delta, a bump): gradually, still a
      // normal of that space, no longer of unit length (normalize(n + dn) is the morphed normal).
      out.type = ga == Geometry::normal ? a : b;
      out.type.length_loss = Type::LengthLoss::offset;
    } else if (vectorish(ga) || vectorish(gb)) {
      out.type.geometry = Geometry::vector;  // a sum of directions is no longer unit length
      out.type.orientation = sum_orientation(add, a.orientation, b.orientation);  // wo + wi is away, like both
    }
    return out;
  }

  // * and /
  const bool a_scalar = a.shape == Shape::scalar, b_scalar = b.shape == Shape::scalar;
  if (ga == Geometry::hpoint || gb == Geometry::hpoint) return homogeneous_product(op, lhs, rhs, shape, op_range, range);
  // (m * vec4(p, 1.0)).xyz / (m * vec4(p, 1.0)).w under an affine map: w is 1, the point is itself.
  if (ga == Geometry::point && op == ast::BinaryOp::Div && rhs.unit_w) {
    out.type = a;
    return out;
  }
  if (ga == Geometry::point || gb == Geometry::point)
    return reject(std::string("cannot ") + verb(op) + " " + both + ": a point cannot be scaled",
                  "subtract another point to get a vector, which can be scaled", code::E_POINT_ARITHMETIC);
  const bool per_axis = op == ast::BinaryOp::Div && !b_scalar && vectorish(gb) && (a_scalar || vectorish(ga) || ga == Geometry::none);
  if (op == ast::BinaryOp::Div && !b_scalar && gb != Geometry::spectrum && gb != Geometry::none && !per_axis)
    return reject("cannot divide by " + name_of(b), "", code::E_INVALID_OPERANDS);
  std::optional<DimSlot> d = combine(da, db, op == ast::BinaryOp::Mul ? 1 : -1);
  if (!d) return reject("dimension exponent overflows in this product", "", code::E_DIMENSION_OVERFLOW);
  if (per_axis) {
    // Component-wise quotients by a vector's components (a slab test's `1.0 / d`, `(lower - o) / d`):
    // a number per axis, no longer a vector of the space.
    if (!a_scalar && !consistent(a.from, b.from))
      return reject("cannot divide " + name_of(a) + " by " + name_of(b) + ": they are in different spaces",
                    space_hint(a.from, b.from), code::E_SPACE_MISMATCH);
    out.type.dim = *d;  // `shape`: the plain vector type
    return out;
  }
  out.type.dim = *d;
  keep_scaled_spelling(out.type.dim, da, db, op == ast::BinaryOp::Div);
  const Geometry g = a_scalar ? gb : ga;
  const Type& geo = a_scalar ? b : a;
  if (a_scalar || b_scalar) {
    // A cosine scaling a unit vector, or a plain multiple of one (`2.0 * n * dot(n, wo)`), is a component along it.
    const DimSlot& geo_dim = a_scalar ? db : da;
    const bool plain_multiple = g == Geometry::vector && geo_dim.state == DimSlot::State::known && geo_dim.value.is_dimensionless();
    if (op == ast::BinaryOp::Mul && (g == Geometry::direction || g == Geometry::normal || plain_multiple))
      out.type.dim = projected_component(*d);
    const Value& scale = a_scalar ? lhs : rhs;
    if ((g == Geometry::direction || g == Geometry::normal) && is_unit_sign(scale)) {
      // ±1 keeps a unit vector unit: `n * faceDirection`, `-1.0 * d`.
      out.type = geo;
      out.type.orientation = scaled_orientation(geo.orientation, scale);
      if (scale.unit_sign) out.type.orientation = Orientation::none;
      return out;
    }
    if (vectorish(g)) {
      out.type.geometry = Geometry::vector;  // a scaled direction or normal is a vector of the scale's dimension
      out.type.from = geo.from;
      out.type.orientation = scaled_orientation(geo.orientation, a_scalar ? lhs : rhs);
      const DimSlot& scale_dim = a_scalar ? da : db;
      out.type.normal_multiple = normal_like(geo) && (scale_dim.state == DimSlot::State::unknown ||
                                                      (scale_dim.is_known() && scale_dim.value.is_dimensionless()));
    } else if (g == Geometry::hpoint) {
      out.type.geometry = Geometry::hpoint;
      out.type.from = geo.from;
      out.type.dim = DimSlot::unknown();
    } else if (g == Geometry::spectrum) {
      out.type.geometry = Geometry::spectrum;
    }
    return out;
  }
  // Component-wise products of two vec3-shaped values.
  if (colour_like(ga) && colour_like(gb)) {
    out.type.geometry = Geometry::spectrum;
    return out;
  }
  if (!consistent(a.from, b.from))
    return reject(std::string("cannot ") + verb(op) + " " + both + ": they are in different spaces", space_hint(a.from, b.from),
                  code::E_SPACE_MISMATCH);
  return out;  // e.g. vector * vector component-wise: a plain vec3 of the product dimension
}

// Homogeneous coordinates carry a power of w (Type::weight): products add the
// weights, quotients subtract them, and a value of weight 0 is dehomogenized:
// h.xy / h.w, or h.xy * (1.0 / h.w), are plain coordinates.
Value Checker::homogeneous_product(ast::BinaryOp op, const Value& lhs, const Value& rhs, Type shape, SourceRange op_range,
                                   SourceRange range) {
  const Type& a = lhs.type;
  const Type& b = rhs.type;
  const bool ha = a.geometry == Geometry::hpoint, hb = b.geometry == Geometry::hpoint;
  if (ha && hb && !consistent(a.from, b.from)) {
    operand_mismatch(std::string("cannot ") + (op == ast::BinaryOp::Mul ? "multiply " : "divide ") + name_of(a) +
                         (op == ast::BinaryOp::Mul ? " and " : " by ") + name_of(b) + ": they are in different spaces",
                     lhs, rhs, op_range, "divide by the w of the same homogeneous point", code::E_SPACE_MISMATCH);
    return error_value(range);
  }
  const int wa = ha ? a.weight : 0, wb = hb ? b.weight : 0;
  const int weight = op == ast::BinaryOp::Mul ? wa + wb : wa - wb;
  Value out;
  out.range = range;
  out.type = shape;
  out.type.dim = DimSlot::unknown();
  const SpaceSlot space = ha ? a.from : b.from;
  if (weight != 0 && weight >= INT8_MIN && weight <= INT8_MAX) {
    out.type.geometry = Geometry::hpoint;
    out.type.from = space;
    out.type.weight = static_cast<std::int8_t>(weight);
  }
  // Weight 0: plain coordinates. Not a point<S>: after a projection they are
  // NDC, not lengths (homogenize(h), or a declared point<S>, says otherwise).
  // The whole vec4 divided by its own w is the point with w = 1, homogenize(h) as a vec4:
  // an affine map then carries it (NDC through the inverse projection, then to world).
  if (weight == 0 && op == ast::BinaryOp::Div && ha && hb && a.shape == Shape::vector && a.rows == 4 && b.shape == Shape::scalar) {
    Type point = Type::vector_of(a.scalar, 3);
    point.geometry = Geometry::point;
    point.from = space;
    point.dim = value_dimension(point, result_.registry);
    out.type.affine = std::make_shared<const Type>(point);
    out.type.affine_w = 1;
  }
  return out;
}

// m2 * m1 of 3×3 maps: the linear part of the composed map. Two rotations compose to a rotation;
// normal matrices (and rotations, their own normal matrices) compose to a normal matrix,
// transpose(inverse(m2 * m1)) = N(m2) * N(m1); a normal matrix with a map that may scale does not.
Value Checker::compose_3x3(const Value& lhs, const Value& rhs, SourceRange op_range, SourceRange range) {
  const Type& a = lhs.type;
  const Type& b = rhs.type;
  const auto normal_or_rigid = [](const Type& t) { return t.normal_matrix || t.geometry == Geometry::rigidmap; };
  const bool normal = a.normal_matrix || b.normal_matrix;
  if (normal && !(normal_or_rigid(a) && normal_or_rigid(b))) {
    operand_mismatch("invalid operands to binary expression (" + name_of(a) + " and " + name_of(b) + ")", lhs, rhs, op_range,
                     "a normal matrix carries normals, and composes only with normal matrices and rotations",
                     code::E_INVALID_OPERANDS);
    return error_value(range);
  }
  if (!consistent(a.from, b.to)) {
    operand_mismatch("cannot compose " + name_of(a) + " with " + name_of(b) + ": the first takes values in " +
                         name_of_space(a.from) + ", the second gives them in " + name_of_space(b.to),
                     lhs, rhs, op_range, space_hint(a.from, b.to), code::E_SPACE_MISMATCH);
    return error_value(range);
  }
  Value out;
  out.range = range;
  out.type = a;
  out.type.from = b.from;
  out.type.to = a.to;
  out.type.normal_matrix = normal;
  out.type.geometry = !normal && a.geometry == Geometry::rigidmap && b.geometry == Geometry::rigidmap ? Geometry::rigidmap
                                                                                                        : Geometry::map;
  return out;
}

// d * d of a length, and the products and quotients of one: how many times a value divides by a
// squared distance (Value::inverse_squares).
void Checker::carry_inverse_squares(const ast::BinaryExpr& node, const Value& lhs, const Value& rhs, Value& out) const {
  if (out.type.is_error() || (node.op != ast::BinaryOp::Mul && node.op != ast::BinaryOp::Div)) return;
  const std::optional<Dimension> length = result_.registry.find_dimension("length");
  const auto is_length = [&](const Value& v) {
    const DimSlot d = value_dimension(v.type, result_.registry);
    return length && v.type.shape == Shape::scalar && d.is_known() && d.value == *length;
  };
  if (node.op == ast::BinaryOp::Mul && is_length(lhs) && is_length(rhs) && node.lhs && node.rhs &&
      print_expression(*node.lhs) == print_expression(*node.rhs)) {
    out.inverse_squares = -1;
    return;
  }
  // x * d * d and x / d / d: the chain's last two factors are the squared distance.
  if (const auto* inner = ast::dyn_cast<ast::BinaryExpr>(ast::without_parens(node.lhs));
      inner && inner->op == node.op && inner->rhs && node.rhs && is_length(rhs) &&
      print_expression(*inner->rhs) == print_expression(*node.rhs)) {
    const auto found = result_.types.find(inner->rhs);
    if (found != result_.types.end() && is_length(Value{.type = found->second})) {
      out.inverse_squares = lhs.inverse_squares + (node.op == ast::BinaryOp::Div ? 1 : -1);
      return;
    }
  }
  const int sign = node.op == ast::BinaryOp::Div ? -1 : 1;
  out.inverse_squares = lhs.inverse_squares + sign * rhs.inverse_squares;
}

// The dimension of a value that divides by written-out squared distances when each 1/d² is the
// solid angle per projected area (sr / (m²·proj)) that inverse_square(d) is.
std::optional<DimSlot> Checker::inverse_square_reading(const Value& value) const {
  if (value.inverse_squares == 0) return std::nullopt;
  const DimensionRegistry& reg = result_.registry;
  const std::optional<Dimension> sr = reg.find_dimension("solid_angle"), proj = reg.find_dimension("proj");
  const DimSlot have = value_dimension(value.type, reg);
  if (!sr || !proj || !have.is_known()) return std::nullopt;
  const Checked<Dimension> per = divide(*sr, *proj);
  const Checked<Dimension> jacobian = per ? power(*per, value.inverse_squares) : per;
  const Checked<Dimension> read = jacobian ? multiply(have.value, *jacobian) : jacobian;
  return read ? std::optional<DimSlot>(DimSlot::known(*read)) : std::nullopt;
}

// Such a value stored where that reading fits.
std::optional<Value> Checker::inverse_square_as_solid_angle(const Type& target, const Value& value) const {
  const DimSlot want = value_dimension(target, result_.registry), have = value_dimension(value.type, result_.registry);
  const std::optional<DimSlot> read = inverse_square_reading(value);
  if (!read || !want.is_known() || !same_dimension(*read, want) || same_dimension(have, want)) return std::nullopt;
  Value out = value;
  out.type.dim = *read;
  out.inverse_squares = 0;
  return out;
}

}  // namespace safegi::detail
