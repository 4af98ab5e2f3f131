// Expressions other than operators and calls: names, literals, assignment,
// members and swizzles, indexing, the conditional operator, initialiser lists.

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include <safegi/parser/printer.hpp>

#include "checker_impl.hpp"
#include "dim_slot.hpp"

namespace safegi::detail {
namespace {

// The type an integer literal's suffix gives it: u, l (int64_t), ul, s (int16_t), us (GL_EXT_shader_explicit_arithmetic_types).
Scalar integer_literal_scalar(std::string_view spelling, bool is_signed) {
  auto lower = [&](std::size_t from_end) { return static_cast<char>(spelling.size() > from_end ? spelling[spelling.size() - 1 - from_end] | 0x20 : 0); };
  const char last = lower(0), before = lower(1);
  if (last == 'l') return before == 'u' ? Scalar::uint64_ : Scalar::int64_;
  if (last == 's') return before == 'u' ? Scalar::uint16_ : Scalar::int16_;
  return is_signed ? Scalar::int_ : Scalar::uint_;
}

// hf: float16_t; lf (a double literal) is LiteralKind::Double.
Scalar float_literal_scalar(std::string_view spelling) {
  const std::size_t n = spelling.size();
  return n >= 2 && (spelling[n - 1] | 0x20) == 'f' && (spelling[n - 2] | 0x20) == 'h' ? Scalar::float16_ : Scalar::float_;
}

// The value a use of `var` reads (one Value, returned in place: identifier() has other returns).
Value variable_value(const Variable& var, const ast::IdentifierExpr& e) {
  Value v;
  v.type = var.type;
  v.range = e.range;
  v.pi_factor = var.pi_constant;
  v.w_divided_at = var.w_divided_at;
  v.lvalue = true;
  v.read_only = var.read_only;
  v.stage_output = var.stage_output;
  v.pi_multiple = var.pi_multiple;
  v.inverse_squares = var.inverse_squares;
  v.length_of = var.length_of;
  v.perpendicular_to = var.perpendicular_to;
  v.unit_sign = var.unit_sign;
  v.plane_normal = var.plane_normal;
  v.constant = var.constant;
  v.number = var.constant ? std::optional<double>(static_cast<double>(*var.constant)) : var.number;
  v.name = e.name;
  if (var.range.valid()) v.origin = var.origin;
  return v;
}

}  // namespace

Value Checker::expr(const ast::Expr* e) {
  // Each kind's Value is built in place and recorded here, then returned without a copy or a move
  // (a Value is large: passing it through record() cost a move per expression).
  Value v = e == nullptr ? error_value({}) : [&]() -> Value {
    switch (e->kind) {
      case ast::NodeKind::IdentifierExpr: return identifier(*static_cast<const ast::IdentifierExpr*>(e));
      case ast::NodeKind::LiteralExpr: return literal(*static_cast<const ast::LiteralExpr*>(e));
      case ast::NodeKind::UnaryExpr: return unary(*static_cast<const ast::UnaryExpr*>(e));
      case ast::NodeKind::BinaryExpr: return binary(*static_cast<const ast::BinaryExpr*>(e));
      case ast::NodeKind::AssignExpr: return assign(*static_cast<const ast::AssignExpr*>(e));
      case ast::NodeKind::TernaryExpr: return ternary(*static_cast<const ast::TernaryExpr*>(e));
      case ast::NodeKind::CallExpr: return call(*static_cast<const ast::CallExpr*>(e));
      case ast::NodeKind::IndexExpr: return index(*static_cast<const ast::IndexExpr*>(e));
      case ast::NodeKind::MemberExpr: return member(*static_cast<const ast::MemberExpr*>(e));
      case ast::NodeKind::MethodCallExpr: return method_call(*static_cast<const ast::MethodCallExpr*>(e));
      case ast::NodeKind::ConvertExpr: return convert(*static_cast<const ast::ConvertExpr*>(e));
      case ast::NodeKind::ParenExpr: {
        Value inner = expr(static_cast<const ast::ParenExpr*>(e)->inner);
        inner.range = e->range;
        return inner;
      }
      case ast::NodeKind::InitializerList:
        report(Diagnostic::error(e->range, "an initializer list can only initialize a declared variable").with_code(code::E_INIT_LIST));
        return error_value(e->range);
      default: return error_value(e->range);
    }
  }();
  if (e == nullptr) return v;
  if (auto [at, inserted] = result_.types.try_emplace(e, v.type); !inserted) at->second = v.type;
  return v;
}

Value Checker::identifier(const ast::IdentifierExpr& e) {
  if (const Variable* var = lookup(e.name)) {
    if (var->builtin && !builtin_available(e.name, e.range, false)) return error_value(e.range);
    symbols_.use_variable(e.name, e.range, var->range, var->type, var->builtin);
    return variable_value(*var, e);
  }
  if (const Unit* unit = result_.registry.find_unit(e.name)) {
    // A unit in an expression is a constant of its dimension (docs/language.md).
    symbols_.use_unit(e.name, e.range, unit->dimension);
    Value v;
    v.type = Type::scalar_of(Scalar::float_);
    v.type.dim = DimSlot::known(unit->dimension);
    v.range = e.range;
    v.read_only = true;
    v.number = unit->scale;
    return v;
  }
  if (e.name.rfind("gl_", 0) == 0) {
    if (const std::string extensions = builtin_variable_extensions(e.name); !extensions.empty()) {
      // Declared in this stage only with an extension (gl_Layer in a vertex shader), which is not enabled.
      std::string names;
      for (std::size_t at = 0; at < extensions.size();) {
        const std::size_t space = std::min(extensions.find(' ', at), extensions.size());
        names += (names.empty() ? "" : " or ") + extensions.substr(at, space - at);
        at = space + 1;
      }
      const std::string first = extensions.substr(0, extensions.find(' '));
      report(Diagnostic::error(e.range, "'" + e.name + "' in " + stage_name(options_.stage) + " shaders requires " + names)
                 .with_code(code::E_VERSION)
                 .with_hint("enable it with '#extension " + first + " : enable'"));
      return error_value(e.range);
    }
    if (const std::string owners = stages_owning_builtin(e.name); !owners.empty()) {
      report(Diagnostic::error(e.range, "'" + e.name + "' is not available in " + stage_name(options_.stage) + " shaders")
                 .with_code(code::E_STAGE_BUILTIN)
                 .with_hint("'" + e.name + "' is a built-in of " + owners + " shaders"));
      return error_value(e.range);
    }
    if (!builtin_available(e.name, e.range, false)) return error_value(e.range);
    // Built-in names this checker does not model (gl_Max* constants, compatibility
    // state, extensions) are left to the driver rather than reported wrongly.
    if (e.name.rfind("gl_Max", 0) == 0 || e.name.rfind("gl_Min", 0) == 0) {
      Value v;
      // The two vector limits (GLSL 4.60 §7.4): ivec3; their components are not folded.
      const bool vector = e.name == "gl_MaxComputeWorkGroupCount" || e.name == "gl_MaxComputeWorkGroupSize";
      v.type = vector ? Type::vector_of(Scalar::int_, 3) : Type::scalar_of(Scalar::int_);
      v.range = e.range;
      v.read_only = true;
      v.constant = builtin_constant(e.name);
      return v;
    }
    return error_value(e.range);
  }
  std::string message = "use of undeclared identifier '" + e.name + "'";
  if (functions_.count(e.name) || builtins_->is_builtin(e.name)) message = "'" + e.name + "' is a function, not a variable";
  report(Diagnostic::error(e.range, message).with_code(code::E_UNDECLARED));
  return error_value(e.range);
}

Value Checker::literal(const ast::LiteralExpr& e) {
  Value v;
  v.range = e.range;
  v.literal = e.literal_kind != ast::LiteralKind::Bool;
  v.zero = e.is_zero && v.literal;
  switch (e.literal_kind) {
    case ast::LiteralKind::Int:
    case ast::LiteralKind::Uint: {
      v.type = Type::scalar_of(integer_literal_scalar(e.spelling, e.literal_kind == ast::LiteralKind::Int));
      const char* text = e.spelling.c_str();
      int base = 10;
      if (e.spelling.size() > 1 && e.spelling[0] == '0') base = (e.spelling[1] == 'x' || e.spelling[1] == 'X') ? 16 : 8;
      unsigned long long value = std::strtoull(text, nullptr, base);
      const int bits = 8 * scalar_bytes(v.type.scalar);
      const unsigned long long mask = bits == 64 ? ~0ull : (1ull << bits) - 1;
      v.constant = static_cast<long long>(value & mask);
      if (!is_float_scalar(v.type.scalar) && v.type.scalar != Scalar::uint_ && v.type.scalar != Scalar::uint16_ &&
          v.type.scalar != Scalar::uint64_ && bits < 64 && *v.constant >= (1ll << (bits - 1)))
        *v.constant -= 1ll << bits;
      v.number = static_cast<double>(*v.constant);
      break;
    }
    case ast::LiteralKind::Float:
      v.type = Type::scalar_of(float_literal_scalar(e.spelling));
      v.number = std::strtod(e.spelling.c_str(), nullptr);
      v.pi_multiple = is_pi_multiple(*v.number);
      // A literal kπ or 1/(kπ) (`#define M_PI 3.14159265359` expanded) is a π constant: which
      // quantity it is depends on its use, as for `const float PI` (docs/language.md, "Gradual typing").
      v.pi_factor = pi_constant(e.spelling, *v.number);
      if (v.pi_factor) {
        v.type.dim = DimSlot::unknown();
        return v;
      }
      break;
    case ast::LiteralKind::Double: v.type = Type::scalar_of(Scalar::double_); v.number = std::strtod(e.spelling.c_str(), nullptr); break;
    case ast::LiteralKind::Bool:
      v.type = Type::scalar_of(Scalar::bool_);
      v.constant = e.spelling == "true" ? 1 : 0;
      return v;
    default:  // strings (GL_EXT_debug_printf): no numeric type
      v.literal = v.zero = false;
      return v;
  }
  // Literal policy: zero fits any dimension, every other literal is dimensionless.
  v.type.dim = v.zero ? DimSlot::zero() : DimSlot::known(Dimension{});
  return v;
}

Value Checker::unary(const ast::UnaryExpr& e) {
  Value v = expr(e.operand);
  if (v.type.is_error()) return error_value(e.range);
  Value out = v;
  out.range = e.range;
  out.lvalue = false;
  out.origin.reset();
  const Type& t = v.type;
  switch (e.op) {
    case ast::UnaryOp::Plus:
    case ast::UnaryOp::Minus:
      if (!t.is_numeric() || t.is_array()) break;
      if (t.geometry == Geometry::point) {
        if (e.op == ast::UnaryOp::Plus) return out;
        // -p is origin - p: the vector from p to its space's origin, the eye in a space declared
        // `: eye`; elsewhere it depends on where the origin is (as normalize(p) and length(p) do).
        if (t.from.is_known() && !result_.registry.is_eye_space(t.from.id)) {
          negated_point(v, e.range);
          return error_value(e.range);
        }
        out.type.geometry = Geometry::vector;
        out.type.orientation = t.orientation == Orientation::shaded ? Orientation::away : Orientation::none;
        out.constant.reset();
        out.number.reset();
        return out;
      }
      if (e.op == ast::UnaryOp::Minus) out.type.orientation = flipped(out.type.orientation);
      if (out.constant && e.op == ast::UnaryOp::Minus) *out.constant = static_cast<long long>(0ull - static_cast<unsigned long long>(*out.constant));
      if (out.number && e.op == ast::UnaryOp::Minus) *out.number = -*out.number;
      return out;
    case ast::UnaryOp::Not:
      if (t.shape == Shape::scalar && t.scalar == Scalar::bool_ && !t.is_array()) {
        out.literal = false;
        if (out.constant) *out.constant = !*out.constant;
        return out;
      }
      break;
    case ast::UnaryOp::BitNot:
      if (t.is_integer() && !t.is_array() && (t.shape == Shape::scalar || t.shape == Shape::vector)) {
        out.literal = false;
        out.constant.reset();
        return out;
      }
      break;
    default:  // ++ and --
      if (!v.lvalue || v.read_only) {
        report(Diagnostic::error(e.operand->range, v.readonly_reference ? "cannot modify readonly memory of the buffer_reference block '" +
                                                                              v.readonly_reference->name + "'"
                                                   : v.lvalue ? "cannot modify read-only variable '" + v.name + "'"
                                                              : "expression is not assignable")
                   .with_code(code::E_NOT_ASSIGNABLE));
        return error_value(e.range);
      }
      if (t.is_numeric() && !t.is_array()) {
        // x++ adds a dimensionless 1: only dimensionless (or unannotated) values may be counted.
        if (t.dim.is_known() && !t.dim.value.is_dimensionless()) {
          report(Diagnostic::error(e.op_range, "cannot increment " + name_of(t) + " by a dimensionless 1")
                     .with_code(code::E_DIMENSION_MISMATCH)
                     .with_highlight(e.operand->range));
          return error_value(e.range);
        }
        out.literal = false;
        out.constant.reset();
        return out;
      }
      break;
  }
  report(Diagnostic::error(e.op_range, "invalid argument type " + name_of(t) + " to unary expression")
             .with_code(code::E_INVALID_OPERANDS)
             .with_highlight(e.operand->range));
  return error_value(e.range);
}

namespace {

// The written name of an l-value made of a variable, indices and members, and
// whether it selects a member of a block or struct; nothing for other forms.
struct LvaluePath {
  std::string text;
  bool has_member = false;
};

std::optional<LvaluePath> lvalue_path(const ast::Expr* e, const std::unordered_map<const ast::Node*, Type>& types) {
  if (const auto* id = ast::dyn_cast<ast::IdentifierExpr>(e)) return LvaluePath{id->name};
  if (const auto* index = ast::dyn_cast<ast::IndexExpr>(e)) {
    std::optional<LvaluePath> base = lvalue_path(index->base, types);
    if (!base || !index->index) return std::nullopt;
    base->text += "[" + print_expression(*index->index) + "]";
    return base;
  }
  if (const auto* member = ast::dyn_cast<ast::MemberExpr>(e)) {
    std::optional<LvaluePath> base = lvalue_path(member->base, types);
    const auto base_type = types.find(member->base);
    if (!base || base_type == types.end()) return std::nullopt;
    base->text += "." + member->member;
    if (base_type->second.shape == Shape::structure && !base_type->second.is_array()) base->has_member = true;
    return base;
  }
  return std::nullopt;
}

}  // namespace

// `vs_out.TangentViewPos`, not the instance alone: the member is what has the
// type. Once a member of a block or struct is selected, the indices and
// swizzles after it are named too (`vs_out.arr[1]`, `vs_out.P.x`); an index
// or a swizzle of a plain variable keeps the variable's name.
std::string Checker::member_path(const ast::Expr* target, const std::string& variable) const {
  std::optional<LvaluePath> path = lvalue_path(target, result_.types);
  return path && path->has_member ? path->text : variable;
}

// `vec3 sum = vec3(0.0);`: an unannotated local whose start is zero, which fits any dimension.
bool Checker::infer_from_zero(bool global, const Type& declared, const Value& init) const {
  return !global && init.zero && !declared.is_annotated() && !declared.is_error() && !declared.is_array() &&
         (declared.shape == Shape::scalar || declared.shape == Shape::vector) && declared.is_floating() &&
         init.type.shape == declared.shape && init.type.rows == declared.rows && !init.type.is_array() &&
         implicitly_converts(init.type.scalar, declared.scalar);  // `vec4 a = vec2(0.0);` is still a GLSL error
}

// A local whose type was inferred from its initializer (no annotation written) is a name,
// not a quantity: `float blinn = pow(…); blinn *= (n + 8.0) / (8.0 * PI);` reuses it for the
// normalised lobe. An assignment of another type rebinds it from there on, in the same
// block; in a nested block (a branch, a loop) the value after it is either, so unknown.
// An annotated variable never changes: the assignment is checked against it.
bool Checker::rebind_inferred_local(const ast::AssignExpr& e, const Value& lhs, const Value& value) {
  const auto* id = ast::dyn_cast<ast::IdentifierExpr>(e.lhs);
  if (id == nullptr || scopes_.size() < 2) return false;
  Variable* var = nullptr;
  std::size_t depth = scopes_.size() - 1;
  for (; depth > 0; --depth)
    if (auto found = scopes_[depth].find(id->name); found != scopes_[depth].end()) {
      var = &found->second;
      break;
    }
  if (var == nullptr || var->builtin || var->read_only) return false;
  Type a = var->type, b = value.type;
  if (!implicitly_converts(b.scalar, a.scalar)) return false;
  b.scalar = a.scalar;
  if (!same_glsl_type(a, b)) return false;
  if (var->zero_start && !a.is_annotated() && b.is_annotated()) {
    // Zero has every dimension: the first annotated value stored (or added) names the type, from
    // any block (a loop's `sum += x`), and later values are checked against it.
    var->type = b;
    var->zero_start = false;
    var->origin = {e.range, "type of '" + id->name + "' set by this assignment (it started at zero)", true};
    return true;
  }
  if (!var->origin.inferred) return false;
  ++muted_;
  const bool fits = check_assignable(lhs.type, value, e.lhs->range, id->name, lhs.origin, "assign");
  --muted_;
  // h /= h.w makes the homogeneous point the point it stands for (w = 1), which fits an hpoint
  // but is no longer one: a map now applies to it as to vec4(p, 1.0).
  const bool divided = a.geometry == Geometry::hpoint && b.affine;
  if (fits && !divided) return false;
  if (depth + 1 == scopes_.size()) {
    var->type = b;
    var->origin = {e.range, "type of '" + id->name + "' set by this assignment", true};
  } else {
    var->type = var->type.plain();
    var->origin = {e.range, "'" + id->name + "' reused for another quantity in a nested block here", true};
  }
  return true;
}

Value Checker::assign(const ast::AssignExpr& e) {
  Value lhs = expr(e.lhs);
  Value rhs = expr(e.rhs);
  if (lhs.type.is_error() || rhs.type.is_error()) return error_value(e.range);
  if (lhs.lvalue && !lhs.read_only && !validate_assignment(e.lhs, lhs)) return error_value(e.range);
  if (!lhs.lvalue || lhs.read_only) {
    std::string message = "expression is not assignable";
    const std::string target = member_path(e.lhs, lhs.name);
    if (lhs.readonly_reference)
      message = "cannot assign to '" + target + "': it is readonly memory of the buffer_reference block '" +
                lhs.readonly_reference->name + "'";
    else if (lhs.lvalue)
      message = target == lhs.name ? "cannot assign to read-only variable '" + lhs.name + "'"
                                   : "cannot assign to '" + target + "': '" + lhs.name + "' is a read-only variable";
    Diagnostic d = Diagnostic::error(e.lhs->range, message).with_code(code::E_NOT_ASSIGNABLE);
    std::optional<Origin> origin = lhs.origin;  // a member's value has none: the note is the instance's declaration
    if (const Variable* var = origin || target == lhs.name ? nullptr : lookup(lhs.name); var && var->range.valid()) origin = var->origin;
    if (origin && lhs.lvalue && !lhs.readonly_reference) d.with_note(Diagnostic::note(origin->range, origin->text));
    report(std::move(d));
    return error_value(e.range);
  }
  Value value = rhs;
  if (e.op != ast::AssignOp::Assign) {
    static const ast::BinaryOp kOps[] = {ast::BinaryOp::Add, ast::BinaryOp::Mul, ast::BinaryOp::Div, ast::BinaryOp::Mod,
                                         ast::BinaryOp::Add, ast::BinaryOp::Sub, ast::BinaryOp::Shl, ast::BinaryOp::Shr,
                                         ast::BinaryOp::BitAnd, ast::BinaryOp::BitXor, ast::BinaryOp::BitOr};
    value = arithmetic(nullptr, kOps[static_cast<int>(e.op)], lhs, rhs, e.op_range, e.range);
    if (value.type.is_error()) return error_value(e.range);
    if (e.op == ast::AssignOp::Div)
      if (std::optional<Value> unit = divided_by_own_length(e.lhs, lhs, rhs, e.range)) value = *unit;
    if (!carry_pi_factor(kOps[static_cast<int>(e.op)], lhs, rhs, value, e.op_range)) return error_value(e.range);
  }
  note_write(e.lhs);
  divided_in_place(e);
  // `sum += x` of a local that starts at zero: the sum is x's quantity (plain + x is x's, unchecked).
  const bool summed = e.op == ast::AssignOp::Add || e.op == ast::AssignOp::Sub;
  if (rebind_inferred_local(e, lhs, summed && !lhs.type.is_annotated() ? rhs : value)) {
    Value out = value;
    out.range = e.range;
    out.lvalue = false;
    out.origin.reset();
    return out;
  }
  if (lhs.stage_output && !homogeneous_part_kept(value, e.lhs->range, member_path(e.lhs, lhs.name))) return error_value(e.range);
  Value stored = value;
  if (lhs.stage_output) stored.type.length_loss = Type::LengthLoss::none;  // the next stage normalizes what it interpolates
  if (!check_assignable(lhs.type, stored, e.lhs->range, member_path(e.lhs, lhs.name), lhs.origin, "assign")) return error_value(e.range);
  Value out = lhs;
  out.range = e.range;
  out.lvalue = false;
  out.origin.reset();
  return out;
}

bool Checker::check_assignable(const Type& target, const Value& value, SourceRange target_range,
                               const std::string& target_name, const std::optional<Origin>& target_origin,
                               const char* action) {
  if (std::optional<Value> radians = pi_multiple_as_angle(target, value))
    return check_assignable(target, *radians, target_range, target_name, target_origin, action);
  if (std::optional<Value> jacobian = inverse_square_as_solid_angle(target, value))
    return check_assignable(target, *jacobian, target_range, target_name, target_origin, action);
  const Type& v = value.type;
  if (target.is_error() || v.is_error()) return true;
  const std::string subject = target_name.empty() ? std::string("a value") : "'" + target_name + "'";
  auto fail = [&](const std::string& what, const std::string& hint, const char* code) {
    Diagnostic d = Diagnostic::error(value.range, what).with_code(code);
    if (target_range.valid() && !(target_range == value.range)) d.with_highlight(target_range);
    if (target_origin && target_origin->range.valid())
      d.with_note(Diagnostic::note(target_origin->range,
                                   target_origin->text + (target_origin->inferred ? " as " + name_of(target) : std::string())));
    add_origin_note(d, value);
    if (!hint.empty()) d.with_hint(hint);
    report(std::move(d));
    return false;
  };
  // "cannot initialize 'x' of type T with a value of type V" (V as `found` has it).
  const auto sentence_for = [&](const Type& found) {
    return std::string(action) == "return"
               ? "cannot return a value of type " + name_of(found) + " from '" + target_name + "', which returns " + name_of(target)
               : std::string("cannot ") + action + " " + subject + " of type " + name_of(target) + " with a value of type " +
                     name_of(found);
  };
  // Built only when a check fails: most assignments pass.
  const auto sentence = [&] { return sentence_for(v); };
  const auto kind_hint = [&]() -> std::string {
    return target.geometry == Geometry::rigidmap && v.geometry == Geometry::map && !value.non_unit_column.empty()
          ? value.non_unit_column + " is a vector of unknown length, not a direction: normalize() it (a cross "
                                    "product of two directions has unit length only when they are perpendicular), or declare "
                                    "the frame without 'rigid'"
          : kind_mismatch_hint(target.geometry, v.geometry);
  };
  // GLSL first: the representation must match, up to implicit scalar conversion.
  Type a = target, b = v;
  const bool unsized = !a.array.empty() && a.array[0] < 0 && !b.array.empty();
  if (unsized) a.array[0] = b.array[0];
  const bool scalar_ok = implicitly_converts(b.scalar, a.scalar);
  b.scalar = a.scalar;
  if (!same_glsl_type(a, b) || !scalar_ok) return fail(sentence(), kind_hint(), code::E_TYPE_MISMATCH);
  if (target.shape == Shape::opaque || target.shape == Shape::structure) return true;
  // Geometric kind: an unannotated (kind-less) side is consistent with any kind.
  if (target.geometry != Geometry::none && v.geometry != Geometry::none && !kind_fits(v.geometry, target.geometry))
    return fail(sentence(), kind_hint(), code::E_KIND_MISMATCH);
  if (is_map(target.geometry) && is_map(v.geometry) && target.normal_matrix != v.normal_matrix &&
      v.geometry != Geometry::rigidmap)
    return fail(sentence(), v.normal_matrix ? "the normal matrix (the inverse transpose) carries normals; the map itself is m"
                                          : "the normal matrix of m is transpose(inverse(m))",
                code::E_KIND_MISMATCH);
  if (!consistent(target.from, v.from) || !consistent(target.to, v.to)) {
    const bool first = !consistent(target.from, v.from);
    return fail(sentence(), first ? space_hint(target.from, v.from) : space_hint(target.to, v.to), code::E_SPACE_MISMATCH);
  }
  const DimSlot found = value_dimension(v, result_.registry);
  if (!value.zero && !consistent(target.dim, found) && !cosine_as_number(target.dim, found))
    return fail(sentence(), physics_hint(target.dim, inverse_square_reading(value).value_or(found), value.range),
                code::E_DIMENSION_MISMATCH);
  if (std::optional<DimSlot> as_pi = pi_factor_misfit(target, value)) {
    Type shown = v;
    shown.dim = *as_pi;
    const std::string taking = ", taking '" + value.pi_factor->name + "' as " + pi_reading(*value.pi_factor, *as_pi);
    if (same_dimension(*as_pi, target.dim))  // steradians, but not 2π or 4π of them
      return fail(sentence_for(shown) + taking + ", which is no hemisphere (2π) or sphere (4π)",
                  "over the sphere the solid angle is 4π sr, over the hemisphere 2π sr: a missing factor of 2 or 4?",
                  code::E_DIMENSION_MISMATCH);
    return fail(sentence_for(shown) + taking + ": no quantity π measures makes it " + name_of(target),
                physics_hint(target.dim, *as_pi, value.range), code::E_DIMENSION_MISMATCH);
  }
  if (v.length_loss != Type::LengthLoss::none && target.length_loss == Type::LengthLoss::none &&
      (target.geometry == Geometry::normal || target.geometry == Geometry::direction)) {
    const std::string name = written_name(value);
    return fail(std::string("cannot ") + action + " " + subject + " of type " + name_of(target) + " with " + not_unit_subject(value) +
                    ": it is not of unit length until normalize()",
                "normalize it first: normalize(" + name + ")", code::E_KIND_MISMATCH);
  }
  if (orientations_clash(target.orientation, v.orientation))
    return fail(sentence(), orientation_hint(value, target.orientation), code::E_ORIENTATION);
  if (target.texel && v.texel && !(glsl_name(*target.texel) == glsl_name(*v.texel) &&
                                   consistent(target.texel->dim, v.texel->dim)))
    return fail(sentence(), "", code::E_TEXEL_MISMATCH);
  // A π constant (or a literal kπ) times known dimensions is not unannotated: pi_factor_misfit above
  // checked it against the target, as one of the quantities kπ measures.
  const bool checked_pi = value.pi_factor && std::abs(value.pi_factor->exponent) == 1 && value.pi_factor->known.is_known();
  if (options_.strict && target.dim.is_known() && found.state == DimSlot::State::unknown && !value.zero && !checked_pi) {
    report(Diagnostic::warning(value.range, std::string("unannotated value used to ") + action + " " + subject + " of type " +
                                                name_of(target))
               .with_code(code::W_IMPLICIT_ANNOTATION));
  }
  return true;
}

Value Checker::ternary(const ast::TernaryExpr& e) {
  condition(e.condition);
  Value a = expr(e.then_expr);
  Value b = expr(e.else_expr);
  if (a.type.is_error() || b.type.is_error()) return error_value(e.range);
  Type ta = a.type, tb = b.type;
  const bool glsl_ok = same_glsl_type(ta, tb) || (ta.shape == tb.shape && ta.rows == tb.rows && ta.columns == tb.columns &&
                                                  ta.array == tb.array && (implicitly_converts(ta.scalar, tb.scalar) ||
                                                                           implicitly_converts(tb.scalar, ta.scalar)));
  const DimSlot da = value_dimension(ta, result_.registry), db = value_dimension(tb, result_.registry);
  // `pointLight ? 1.0 : max(dot(n, l), 0.0)`: a literal beside a cosine is a cosine (of 0), as a bound is.
  const auto cosine_beside_literal = [&](const Value& literal, const DimSlot& literal_dim, const DimSlot& other) {
    return literal.literal && literal_dim.is_known() && literal_dim.value.is_dimensionless() &&
           cosine_as_number(DimSlot::known(Dimension{}), other);
  };
  const bool a_takes_cosine = cosine_beside_literal(a, da, db), b_takes_cosine = cosine_beside_literal(b, db, da);
  const bool annotations_ok = (kind_fits(ta.geometry, tb.geometry) || kind_fits(tb.geometry, ta.geometry) ||
                               ta.geometry == Geometry::none || tb.geometry == Geometry::none) &&
                              consistent(ta.from, tb.from) && consistent(ta.to, tb.to) &&
                              (a.zero || b.zero || a_takes_cosine || b_takes_cosine || consistent(da, db));
  if (!glsl_ok || !annotations_ok) {
    Diagnostic d = Diagnostic::error(e.range, "the branches of '?:' have different types, " + name_of(ta) + " and " + name_of(tb))
                       .with_code(glsl_ok ? code::E_DIMENSION_MISMATCH : code::E_TYPE_MISMATCH)
                       .with_highlight(e.then_expr->range)
                       .with_highlight(e.else_expr->range);
    if (glsl_ok) {
      std::string hint = physics_hint(da, db);
      if (!hint.empty()) d.with_hint(hint);
    }
    report(std::move(d));
    return error_value(e.range);
  }
  Value out;
  out.range = e.range;
  out.type = a.zero || a_takes_cosine ? tb : ta;
  if (ta.geometry != tb.geometry && is_map(ta.geometry) && is_map(tb.geometry)) out.type.geometry = Geometry::map;  // rigid or affine
  if (implicitly_converts(ta.scalar, tb.scalar) && ta.scalar != tb.scalar) out.type.scalar = tb.scalar;
  if (da.state == DimSlot::State::unknown || db.state == DimSlot::State::unknown) out.type.dim = DimSlot::unknown();
  if (ta.orientation != tb.orientation) out.type.orientation = Orientation::none;  // `front ? wo : -wo`
  // `c ? angleInDegrees : PI / 4.0`: the branch with a π constant is checked where the value is stored.
  if (da.state == DimSlot::State::unknown && db.state != DimSlot::State::unknown && a.pi_factor) out.pi_factor = a.pi_factor;
  if (db.state == DimSlot::State::unknown && da.state != DimSlot::State::unknown && b.pi_factor) out.pi_factor = b.pi_factor;
  out.zero = a.zero && b.zero;
  out.unit_sign = is_unit_sign(a) && is_unit_sign(b) && out.type.shape == Shape::scalar;
  return out;
}

void Checker::condition(const ast::Expr* e) {
  if (!e) return;
  Value v = expr(e);
  if (v.type.is_error()) return;
  if (!(v.type.shape == Shape::scalar && v.type.scalar == Scalar::bool_ && !v.type.is_array()))
    report(Diagnostic::error(e->range, "condition must be a bool, found " + name_of(v.type)).with_code(code::E_CONDITION_TYPE));
}

Value Checker::index(const ast::IndexExpr& e) {
  Value base = expr(e.base);
  Value idx = expr(e.index);
  if (base.type.is_error() || idx.type.is_error()) return error_value(e.range);
  if (!(idx.type.shape == Shape::scalar && idx.type.is_integer() && !idx.type.is_array())) {
    report(Diagnostic::error(e.index->range, "array subscript is not an integer: " + name_of(idx.type)).with_code(code::E_INDEX_TYPE));
    return error_value(e.range);
  }
  Value out = base;
  out.range = e.range;
  out.constant.reset();
  out.literal = false;
  out.origin.reset();
  const Type& t = base.type;
  int size = -1;
  if (t.is_array()) {
    size = t.array[0];
    out.type = t.element();
  } else if (t.shape == Shape::vector) {
    size = t.rows;
    out.type = Type::scalar_of(t.scalar);
    out.type.dim = value_dimension(t, result_.registry);
    if (t.geometry == Geometry::hpoint) keep_homogeneous(out.type, t);
  } else if (t.shape == Shape::matrix) {
    size = t.columns;
    out.type = Type::vector_of(t.scalar, t.rows);
    out.type.dim = is_map(t.geometry) ? DimSlot::unknown() : t.dim;
    if (idx.constant) map_column(out.type, t, *idx.constant);
  } else if (t.shape == Shape::structure && t.structure && t.structure->buffer_reference) {
    // GL_EXT_buffer_reference2: r[i] is r + i, a reference (glslang: indices add up, r[i][j] is r + i + j).
    if (!buffer_reference2(e.range, "indexing a buffer reference")) return error_value(e.range);
    out.lvalue = false;
    return out;
  } else {
    report(Diagnostic::error(e.base->range, "subscripted value of type " + name_of(t) + " is not an array, vector or matrix")
               .with_code(code::E_INDEX_BASE));
    return error_value(e.range);
  }
  if (idx.constant && size > 0 && (*idx.constant < 0 || *idx.constant >= size)) {
    report(Diagnostic::error(e.index->range, "index " + std::to_string(*idx.constant) + " is out of range for " + name_of(t))
               .with_code(code::E_INDEX_RANGE));
    return error_value(e.range);
  }
  return out;
}

Value Checker::member(const ast::MemberExpr& e) {
  Value base = expr(e.base);
  if (base.type.is_error()) return error_value(e.range);
  const Type& t = base.type;
  Value out = base;
  out.range = e.range;
  out.constant.reset();
  out.literal = false;
  out.origin.reset();
  if (t.shape == Shape::structure && !t.is_array()) {
    for (const StructField& f : t.structure->fields) {
      if (f.name == e.member) {
        symbols_.use_field(t.structure, f.name, e.member_range, f.type);
        out.type = f.type;
        if (t.structure->buffer_reference) {
          // The reference may be read-only (a uniform's member, a const); the memory it
          // refers to is writable unless its block or this member says readonly.
          out.lvalue = true;
          out.read_only = t.structure->read_only || f.read_only;
          out.readonly_reference = out.read_only ? t.structure : nullptr;
        }
        return out;
      }
    }
    report(Diagnostic::error(e.member_range, "no member named '" + e.member + "' in '" + t.structure->name + "'")
               .with_code(code::E_NO_MEMBER));
    return error_value(e.range);
  }
  if ((t.shape == Shape::vector || t.shape == Shape::scalar) && !t.is_array()) {
    static const char* const kSets[] = {"xyzw", "rgba", "stpq"};
    const std::string& s = e.member;
    int set = -1;
    bool ok = !s.empty() && s.size() <= 4;
    for (std::size_t i = 0; ok && i < s.size(); ++i) {
      int found = -1, position = -1;
      for (int k = 0; k < 3; ++k) {
        const char* p = std::strchr(kSets[k], s[i]);
        if (p && s[i] != '\0') {
          found = k;
          position = static_cast<int>(p - kSets[k]);
        }
      }
      if (found < 0 || (set >= 0 && found != set) || position >= t.rows) ok = false;
      set = found;
    }
    if (!ok) {
      report(Diagnostic::error(e.member_range, "invalid swizzle '" + s + "' on " + name_of(t)).with_code(code::E_SWIZZLE));
      return error_value(e.range);
    }
    bool repeated = false;
    for (std::size_t i = 0; i < s.size(); ++i)
      for (std::size_t j = i + 1; j < s.size(); ++j) repeated = repeated || s[i] == s[j];
    const bool identity = static_cast<int>(s.size()) == t.rows && s == std::string(kSets[set]).substr(0, s.size());
    out.unit_w = false;
    out.homogeneous_w = t.geometry == Geometry::hpoint && t.rows == 4 && (s == "w" || s == "a" || s == "q");
    if (std::optional<Type> part = affine_part(t, s)) {
      out.type = *part;
    } else if (!identity) {
      out.type = Type::vector_of(t.scalar, static_cast<int>(s.size()));
      out.type.dim = t.geometry == Geometry::hpoint ? DimSlot::unknown() : value_dimension(t, result_.registry);
      if (t.geometry == Geometry::hpoint) keep_homogeneous(out.type, t);
      if (s == "z" && frame_cosine(t)) out.type.dim = DimSlot::known(*frame_cosine(t));
      out.unit_w = t.affine && t.affine_w == 1 && t.rows == 4 && (s == "w" || s == "a" || s == "q");
    }
    out.lvalue = base.lvalue && !repeated;
    return out;
  }
  report(Diagnostic::error(e.member_range, "member reference base type " + name_of(t) + " is not a structure or vector")
             .with_code(code::E_NO_MEMBER));
  return error_value(e.range);
}

Value Checker::initializer_list(const ast::InitializerList& e, const Type& expected) {
  Value out;
  out.range = e.range;
  out.type = expected;
  if (expected.is_error()) return record(&e, out);
  auto element_of = [&](std::size_t i) -> std::optional<Type> {
    if (expected.is_array()) return expected.element();
    if (expected.shape == Shape::structure) {
      if (i < expected.structure->fields.size()) return expected.structure->fields[i].type;
      return std::nullopt;
    }
    if (expected.shape == Shape::matrix) {
      Type column = Type::vector_of(expected.scalar, expected.rows);
      column.dim = expected.dim;
      return column;
    }
    if (expected.shape == Shape::vector) {
      Type component = Type::scalar_of(expected.scalar);
      component.dim = value_dimension(expected, result_.registry);
      return component;
    }
    return std::nullopt;
  };
  for (std::size_t i = 0; i < e.elements.size(); ++i) {
    std::optional<Type> want = element_of(i);
    if (!want) {
      report(Diagnostic::error(e.elements[i]->range, "excess elements in initializer list for " + name_of(expected))
                 .with_code(code::E_INIT_LIST));
      break;
    }
    if (const auto* nested = ast::dyn_cast<ast::InitializerList>(e.elements[i])) {
      if (nested->elements.empty()) {  // glslang: "wrong number of structure members"
        report(Diagnostic::error(nested->range, "an empty initializer '{}' initializes a whole variable, not an element of a list")
                   .with_code(code::E_INIT_LIST));
        continue;
      }
      initializer_list(*nested, *want);
      continue;
    }
    Value v = expr(e.elements[i]);
    check_assignable(*want, v, {}, "", std::nullopt, "initialize");
  }
  return record(&e, out);
}

}  // namespace safegi::detail
