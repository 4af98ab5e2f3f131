// Calls: built-in functions (by the signature table), user functions and
// generic functions (unification over dimensions and spaces), constructors
// and casts, and the map operators routed through the table.

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "checker_impl.hpp"
#include "dim_slot.hpp"

namespace safegi::detail {
namespace {

// A caller's own generic variables are rigid during a call: they are
// represented as fresh base dimensions / spaces beyond the registry's.
constexpr BaseId kRigidBase = 1u << 24;
constexpr std::uint32_t kRigidSpace = 1u << 24;

std::optional<Dimension> rigid(const DimSlot& s) {
  if (s.state == DimSlot::State::known) return s.value;
  if (s.state != DimSlot::State::generic) return std::nullopt;
  Dimension d = s.term.constant;
  for (const auto& [v, k] : s.term.variables) {
    Checked<Dimension> m = multiply(d, Dimension::base(kRigidBase + v, k));
    if (!m) return std::nullopt;
    d = *m;
  }
  return d;
}

DimSlot unrigid(const Dimension& d) {
  DimTerm t;
  std::vector<Factor> plain;
  for (const Factor& f : d.factors()) {
    if (f.base >= kRigidBase) t.variables.push_back({f.base - kRigidBase, f.exponent});
    else plain.push_back(f);
  }
  t.constant = *Dimension::from_factors(plain);
  if (t.variables.empty()) return DimSlot::known(t.constant);
  return DimSlot::generic(t);
}

std::optional<SpaceTerm> rigid(const SpaceSlot& s) {
  if (s.state == SpaceSlot::State::known) return SpaceTerm::space(s.id);
  if (s.state == SpaceSlot::State::generic) return SpaceTerm::space(kRigidSpace + s.id);
  return std::nullopt;
}

SpaceSlot unrigid(SpaceId s) { return s >= kRigidSpace ? SpaceSlot::generic(s - kRigidSpace) : SpaceSlot::known(s); }

std::string arguments_text(const std::vector<Value>& args, const Checker& c) {
  std::string out;
  for (const Value& a : args) out += (out.empty() ? "" : ", ") + c.name_of(a.type);
  return out;
}

}  // namespace

bool Checker::extension_name(const std::string& name) {
  auto ends = [&](const char* suffix) {
    const std::string s = suffix;
    return name.size() > s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0;
  };
  auto starts = [&](const char* prefix) { return name.rfind(prefix, 0) == 0; };
  if (ends("ARB") || ends("EXT") || ends("NV") || ends("AMD") || ends("KHR") || ends("INTEL") || ends("QCOM")) return true;
  if (starts("subgroup") || starts("anyInvocation") || starts("allInvocations") || starts("ballot") || starts("readInvocation") ||
      starts("readFirstInvocation") || starts("nonuniform") || starts("traceRay") || starts("reportIntersection") ||
      starts("executeCallable") || starts("debugPrintf") || starts("coopMat"))
    return true;
  // The bit casts and packings of the explicit arithmetic types not in builtins.def.
  for (const char* p : {"doubleBitsTo", "int64BitsTo", "uint64BitsTo", "packInt", "packUint", "unpackInt", "unpackUint",
                        "packFloat2x16", "unpackFloat2x16", "float16BitsTo", "int16BitsTo", "uint16BitsTo", "halfBitsTo",
                        "pack8", "pack16", "pack32", "pack64", "unpack8", "unpack16", "unpack32"})
    if (starts(p)) return true;
  return false;
}

// `dot(n, lightEuler)`: a vec3 of angles is no vector of a space (its components are rotations
// about three axes, not coordinates along them), whatever a geometric built-in makes of it beside
// one. The direction such angles describe is a column of the rotation built from them.
bool Checker::angles_as_vector(const std::string& name, const std::vector<Value>& args) {
  if (!builtin_argument_rule(name, ArgumentRule::no_angle_triples)) return true;
  const std::optional<BaseId> angle = result_.registry.find_base("angle");
  const auto spatial = [](const Value& v) { return v.type.geometry != Geometry::none && v.type.geometry != Geometry::spectrum; };
  if (!angle || std::none_of(args.begin(), args.end(), spatial)) return true;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const Type& t = args[i].type;
    if (t.shape != Shape::vector || spatial(args[i]) || t.dim.state != DimSlot::State::known || t.dim.value.exponent(*angle) == 0)
      continue;
    Diagnostic d = Diagnostic::error(args[i].range, "argument " + std::to_string(i + 1) + " of '" + name + "' is " + name_of(t) +
                                                        ", a triple of angles, beside a vector of a space: angles (Euler angles) "
                                                        "are rotations about axes, not coordinates along them")
                       .with_code(code::E_DIMENSION_MISMATCH);
    add_origin_note(d, args[i]);
    d.with_hint("the direction a rotation points is a column of its matrix, or (sin θ cos φ, sin θ sin φ, cos θ) of two angles");
    report(std::move(d));
    return false;
  }
  return true;
}

bool Checker::atomic_overload_available(const std::string& name, const std::vector<Value>& args, SourceRange where) {
  const LanguageLevel* level = language();
  if (!level || args.empty()) return true;
  auto need = [&](const char* extension, const std::string& what) {
    if (level->extension_enabled(extension)) return true;
    reject(where, what + " requires " + extension, code::E_VERSION, "enable it with '#extension " + std::string(extension) + " : enable'");
    return false;
  };
  const char* scope_semantics = "GL_KHR_memory_scope_semantics";
  if (name == "memoryBarrier") return need(scope_semantics, "memoryBarrier(scope, storage, semantics)");
  const bool image = name.rfind("imageAtomic", 0) == 0;
  const bool buffer = name.rfind("atomic", 0) == 0 && name.rfind("atomicCounter", 0) != 0;
  if (!image && !buffer) return true;
  const std::string op = name.substr(image ? 11 : 6);
  const Type& target = args[0].type;
  // The forms with (scope, storage semantics, semantics): more than 3 arguments, or for an image more
  // than its coordinates, sample and data (glslang's builtInOpCheck).
  const bool multisample = image && target.opaque.find("MS") != std::string::npos;
  if (args.size() > (image ? (multisample ? 5u : 4u) : 3u) && op != "Load" && op != "Store" &&
      !need(scope_semantics, "'" + name + "' with scope and semantics"))
    return false;
  const bool float32_64 = image ? target.opaque.rfind("image", 0) == 0 : target.scalar == Scalar::float_ || target.scalar == Scalar::double_;
  const bool float16 = !image && target.scalar == Scalar::float16_;
  if (!float32_64 && !float16) return true;
  const std::string what = "'" + name + "' of " + (image ? "a float image" : name_of(target));
  const bool add_like = op == "Add" || op == "Exchange" || op == "Load" || op == "Store";
  if (image && op == "Exchange") return true;  // GLSL 4.50's imageAtomicExchange(float)
  // GL_NV_shader_atomic_float (OpenGL; Mesa, piglit): add and exchange of a float, in memory or a float image.
  if ((op == "Add" || op == "Exchange") && (image || target.scalar == Scalar::float_) &&
      level->extension_enabled("GL_NV_shader_atomic_float"))
    return true;
  if (float32_64 && add_like) return need("GL_EXT_shader_atomic_float", what);
  if (add_like || op == "Min" || op == "Max") return need("GL_EXT_shader_atomic_float2", what);
  reject(where, what + ": only integer " + (image ? "images" : "values") + " have atomic " + op, code::E_NO_OVERLOAD);
  return false;
}

Value Checker::call(const ast::CallExpr& e) {
  if (e.constructor_type) return constructor(e);
  std::vector<Value> args;
  bool bad = false;
  for (const ast::Expr* a : e.args) {
    args.push_back(expr(a));
    bad = bad || args.back().type.is_error();
  }
  if (std::optional<Value> v = subroutine_call(e, args)) return *v;
  validate_call_placement(e);
  if (auto it = functions_.find(e.callee); it != functions_.end()) {
    if (bad) {
      symbols_.use_function(e.callee, e.callee_range, it->second.front().decl, it->second.front().result);
      return error_value(e.range);
    }
    return user_call(e, it->second, args);
  }
  if (const std::vector<Signature>* sigs = builtins_->find(e.callee)) {
    if (!builtin_available(e.callee, e.callee_range, true)) return error_value(e.range);
    if (bad) return error_value(e.range);
    if (e.callee == "nonuniformEXT" && args.size() == 1) {
      // GL_EXT_nonuniform_qualifier: nonuniformEXT(x) is x, of any type (an index, a sampler built from a
      // texture, a block member), dimension and space kept; builtins.def's rows are for completion and hover.
      Value v = args.front();
      v.range = e.range;
      v.lvalue = false;
      v.origin.reset();
      symbols_.use_builtin_function(e.callee, e.callee_range, "", v.type);
      return v;
    }
    Value v = builtin_call(&e, e.callee, *sigs, args, e.callee_range, e.range);
    if (!v.type.is_error() && !atomic_overload_available(e.callee, args, e.callee_range)) return error_value(e.range);
    if (!v.type.is_error() && !unit_length_arguments(e.callee, args)) return error_value(e.range);
    if (!v.type.is_error() && !homogeneous_arguments(e.callee, args)) return error_value(e.range);
    if (!v.type.is_error() && !angles_as_vector(e.callee, args)) return error_value(e.range);
    if (e.callee == "length" && e.args.size() == 1 && !v.type.is_error()) v.length_of = length_of_variable(e.args[0]);
    if (!v.type.is_error()) carry_perpendicular(e, args, v);
    const auto info = result_.calls.find(&e);
    symbols_.use_builtin_function(e.callee, e.callee_range, info == result_.calls.end() ? "" : info->second.signature, v.type);
    return v;
  }
  if (auto s = structs_.find(e.callee); s != structs_.end()) {
    // A struct constructor the parser could not tell from a call.
    Value out;
    out.range = e.range;
    out.type.shape = Shape::structure;
    out.type.structure = s->second;
    return out;
  }
  std::string message = "use of undeclared function '" + e.callee + "'";
  if (lookup(e.callee)) message = "called object '" + e.callee + "' is not a function";
  if (e.callee.rfind("gl", 0) == 0 || bad || extension_name(e.callee)) return error_value(e.range);  // unmodelled extension built-ins
  report(Diagnostic::error(e.callee_range, message).with_code(code::E_UNDECLARED_FUNCTION));
  return error_value(e.range);
}

Value Checker::method_call(const ast::MethodCallExpr& e) {
  Value base = expr(e.base);
  if (base.type.is_error()) return error_value(e.range);
  if (e.method != "length" || !e.args.empty()) {
    report(Diagnostic::error(e.method_range, "unknown method '" + e.method + "'; GLSL has only .length()").with_code(code::E_METHOD));
    return error_value(e.range);
  }
  const Type& t = base.type;
  Value out;
  out.range = e.range;
  out.type = Type::scalar_of(Scalar::int_);
  if (t.is_array()) {
    if (t.array[0] > 0) out.constant = t.array[0];
  } else if (t.shape == Shape::vector) {
    out.constant = t.rows;
  } else if (t.shape == Shape::matrix) {
    out.constant = t.columns;
  } else {
    report(Diagnostic::error(e.method_range, ".length() needs an array, vector or matrix, not " + name_of(t)).with_code(code::E_METHOD));
    return error_value(e.range);
  }
  return out;
}

Value Checker::builtin_call(const ast::CallExpr* node, const std::string& name, const std::vector<Signature>& sigs,
                            std::vector<Value>& args, SourceRange callee_range, SourceRange call_range) {
  if (!has_signature(sigs.front().rule)) return rule_call(node, sigs.front(), args, call_range);
  if (std::optional<Value> v = map_matrix_call(name, args, call_range)) return *v;
  radians_of_pi_multiple(name, args);
  std::vector<ArgInfo> infos;
  for (const Value& a : args) infos.push_back({a.type, a.lvalue});
  std::optional<ShapeMatch> match = match_shapes(sigs, infos);
  if (!match) {
    Diagnostic d = Diagnostic::error(callee_range, "no matching overload for call to '" + name + "(" + arguments_text(args, *this) + ")'")
                       .with_code(code::E_NO_OVERLOAD);
    for (const Value& a : args) d.with_highlight(a.range);
    std::string candidates;
    int shown = 0;
    for (const Signature& s : sigs) {
      if (s.rule == BuiltinRule::point_misuse) continue;
      if (shown++ == 4) {
        candidates += ", …";
        break;
      }
      candidates += (candidates.empty() ? "" : ", ") + name + "(" + s.text.substr(0, s.text.find(" ->")) + ")";
    }
    d.with_hint("candidates: " + candidates);
    report(std::move(d));
    return error_value(call_range);
  }
  const Signature& sig = *match->signature;
  if (sig.rule == BuiltinRule::point_misuse && (name == "normalize" || name == "length") && args.size() == 1 &&
      args[0].type.from.is_known() && result_.registry.is_eye_space(args[0].type.from.id)) {
    // In a space whose origin is the eye a point is the vector from the eye to it: normalize(P) is
    // the direction of the eye's ray, toward P; length(P) its distance.
    Value out;
    out.range = call_range;
    out.type = args[0].type;
    if (name == "length") {
      out.type = Type::scalar_of(Scalar::float_);
      out.type.dim = value_dimension(args[0].type, result_.registry);
    } else {
      out.type.geometry = Geometry::direction;
      out.type.dim = DimSlot::known(Dimension{});
      out.type.orientation = args[0].type.orientation == Orientation::shaded ? Orientation::toward : Orientation::none;
    }
    return out;
  }
  if (sig.rule == BuiltinRule::point_misuse) {
    point_given_for_vector(name, sig, args);
    return error_value(call_range);
  }
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (sig.params[i].is_out && (!args[i].lvalue || args[i].read_only)) {
      report(Diagnostic::error(args[i].range, "argument " + std::to_string(i + 1) + " of '" + name +
                                                  "' is an out parameter and needs a writable variable")
                 .with_code(code::E_NOT_ASSIGNABLE));
      return error_value(call_range);
    }
  }
  CallShape shape;
  for (const SigType& p : sig.params) shape.params.push_back(instantiate_shape(p, *match));
  shape.result = instantiate_shape(sig.result, *match, true);
  shape.dim_params = &sig.dim_params;
  shape.space_params = &sig.space_params;

  if (sig.rule == BuiltinRule::pow && args.size() == 2) {
    // float<D> ^ n with n an integer constant: the result is D^n.
    const DimSlot base = value_dimension(args[0].type, result_.registry);
    const bool dimensioned = base.state == DimSlot::State::generic ||
                             (base.state == DimSlot::State::known && !base.value.is_dimensionless() &&
                              !cosine_as_number(DimSlot::known(Dimension{}), base));  // a lobe: pow(cos θ, n)
    if (dimensioned) {
      const std::optional<double> n = args[1].number;
      if (!n || std::floor(*n) != *n || std::fabs(*n) > 1e6) {
        Diagnostic d = Diagnostic::error(args[1].range, "pow of " + name_of(args[0].type) +
                                                            " needs a constant integer exponent (or a dimensionless base)")
                           .with_code(code::E_POW_EXPONENT)
                           .with_highlight(args[0].range);
        report(std::move(d));
        return error_value(call_range);
      }
      std::optional<DimSlot> d = raise(base, static_cast<long long>(*n));
      if (!d) {
        report(Diagnostic::error(call_range, "dimension exponent overflows in pow").with_code(code::E_DIMENSION_OVERFLOW));
        return error_value(call_range);
      }
      Value out;
      out.range = call_range;
      out.type = shape.result;
      out.type.dim = *d;
      out.type.geometry = args[0].type.geometry == Geometry::spectrum ? Geometry::spectrum : Geometry::none;
      return out;
    }
  }

  if (sig.rule == BuiltinRule::angle_unit && args.size() == 1)
    if (std::optional<Value> v = angle_conversion(name, args[0], shape.result, call_range)) return *v;

  std::optional<Type> result = unify_call(name, shape, args, call_range);
  if (!result) return error_value(call_range);
  // normalize() of an unannotated vector is of unit length, but whether it is a normal (whose
  // cosines are projected) is as unknown as the vector was: it stays `?`.
  // A vec4(v, 0.0) of a vector keeps w = 0, so its normalization is vec4(normalize(v), 0.0).
  if (name == "normalize" && result->geometry == Geometry::none && args[0].type.dim.state == DimSlot::State::unknown) {
    result->dim = DimSlot::unknown();
    const Type& arg = args[0].type;
    if (arg.affine && arg.affine_w == 0 && vectorish(arg.affine->geometry)) {
      Type unit = *arg.affine;
      if (unit.geometry == Geometry::vector) unit.geometry = Geometry::direction;
      unit.dim = DimSlot::known(Dimension{});
      unit.length_loss = Type::LengthLoss::none;
      result->affine = std::make_shared<const Type>(std::move(unit));
      result->affine_w = 0;
    }
  }
  std::optional<Orientation> orientation = builtin_orientation(name, args, call_range);
  if (!orientation) return error_value(call_range);
  if (result->geometry == Geometry::vector || result->geometry == Geometry::direction || result->geometry == Geometry::normal ||
      (result->geometry == Geometry::point && *orientation == Orientation::shaded) ||
      (name == "dot" && result->shape == Shape::scalar))
    result->orientation = *orientation;
  std::vector<DimSlot> argument_dims;
  for (const Value& a : args) argument_dims.push_back(value_dimension(a.type, result_.registry));
  keep_shared_spelling(result->dim, argument_dims);  // max(k, 0.0) of a float<inv_length> is one
  // A spectrum through a component-wise built-in (min, max, mix, clamp, abs, …) stays a spectrum.
  if (result->geometry == Geometry::none && sig.result.size == SizeClass::gen && result->rows == 3) {
    bool all_spectra = false, other = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
      if (sig.params[i].size != SizeClass::gen || args[i].type.shape != Shape::vector) continue;
      if (args[i].type.geometry == Geometry::spectrum) all_spectra = true;
      else if (args[i].type.geometry != Geometry::none) other = true;
    }
    if (all_spectra && !other) result->geometry = Geometry::spectrum;
  }
  if (node) {
    CallInfo info;
    info.builtin = name;
    info.signature = sig.text;
    const Geometry first = sig.params.empty() ? Geometry::none : sig.params[0].type.geometry;
    const Geometry second = sig.params.size() > 1 ? sig.params[1].type.geometry : Geometry::none;
    if (second == Geometry::hpoint && (name == "transform" || name == "project")) {
      info.op = GeometricOp::transform_homogeneous;
    } else if (name == "transform" || name == "transform_normal") {
      if (first == Geometry::projmap) info.op = GeometricOp::project;
      else if (second == Geometry::point) info.op = GeometricOp::transform_point;
      else if (sig.rule == BuiltinRule::normal_transform) info.op = GeometricOp::transform_normal;
      else info.op = GeometricOp::transform_vector;
    } else if (name == "project") {
      info.op = GeometricOp::project;
    } else if (name == "homogenize") {
      info.op = GeometricOp::homogenize;
    } else if (name == "inverse_square") {
      info.op = GeometricOp::inverse_square;
    } else if (name == "compose") {
      info.op = GeometricOp::compose;
    } else if (name == "inverse" && is_map(first)) {
      info.op = GeometricOp::inverse;
    }
    result_.calls[node] = info;
  }
  Value out;
  out.range = call_range;
  out.type = *result;
  return out;
}

// -p of a point of a space whose origin is not the eye.
void Checker::negated_point(const Value& p, SourceRange range) {
  const std::string space = name_of_space(p.type.from);
  const std::string q = p.name.empty() ? "p" : written_name(p);
  Diagnostic d = Diagnostic::error(range, "cannot negate " + name_of(p.type) + (p.name.empty() ? "" : " '" + q + "'") +
                                              ": -p is the vector from p to " + space +
                                              "'s origin, which depends on where that origin is")
                     .with_code(code::E_POINT_ARITHMETIC);
  add_origin_note(d, p);
  // A camera's space by its name: its origin is likely the eye, which the declaration can say.
  const bool camera_like = space.find("view") != std::string::npos || space.find("eye") != std::string::npos ||
                           space.find("cam") != std::string::npos;
  d.with_hint("the vector from " + q + " to another point e is e - " + q + "; " +
              (camera_like ? "if " + space + "'s origin is the eye, declare it so: space " + space + " : eye;"
                           : "if " + q + " is measured from " + space + "'s origin, say so: -vector<" + space + ">(" + q + ")"));
  report(std::move(d));
}

void Checker::point_given_for_vector(const std::string& name, const Signature& sig, const std::vector<Value>& args) {
  std::size_t i = 0;
  while (i + 1 < args.size() && sig.params[i].type.geometry != Geometry::point) ++i;
  const Value& p = args[i];
  const std::string q = p.name.empty() ? "p" : written_name(p);  // `m[3].xyz`, not the matrix `m`
  const std::string what = name_of(p.type) + (p.name.empty() ? std::string() : " '" + q + "'");
  const std::string origin = "if it is measured from the origin of " + name_of_space(p.type.from) + ", say so: vector<" +
                             name_of_space(p.type.from) + ">(" + q + ")";
  std::string message, hint;
  if (name == "normalize") {
    message = "cannot normalize " + what + ": a point is a position, not a direction";
    hint = "the direction from p towards " + q + " is normalize(" + q + " - p); " + origin;
  } else if (name == "length") {
    message = "cannot take the length of " + what + ": a point is a position, and its length would depend on where " +
              name_of_space(p.type.from) + "'s origin is";
    hint = "distance(" + q + ", p) or length(" + q + " - p) measure between two points; " + origin;
  } else {
    message = "'" + name + "' needs vectors, directions or normals, not " + what + ": a point is a position";
    hint = "subtract the point it is measured from (" + q + " - p is a vector); " + origin;
  }
  Diagnostic d = Diagnostic::error(p.range, message).with_code(code::E_POINT_ARITHMETIC);
  add_origin_note(d, p);
  d.with_hint(hint);
  report(std::move(d));
}

std::optional<Value> Checker::geometric_operator(const ast::Node* node, const std::string& builtin, const Value& lhs,
                                                 const Value& rhs, SourceRange range) {
  std::vector<Value> args{lhs, rhs};
  const std::vector<Signature>* sigs = builtins_->find(builtin);
  std::vector<ArgInfo> infos{{lhs.type, false}, {rhs.type, false}};
  if (!sigs || !match_shapes(*sigs, infos)) {
    std::string message = "invalid operands to binary expression (" + name_of(lhs.type) + " and " + name_of(rhs.type) + ")";
    std::string hint = is_map(lhs.type.geometry) ? "a map applies to a point, vector, direction or normal of its source space" : "";
    if (is_map(lhs.type.geometry) && is_map(rhs.type.geometry)) {
      message = "cannot compose " + name_of(lhs.type) + " with " + name_of(rhs.type);
      if (rhs.type.geometry == Geometry::projmap) {
        message += ": the projective map gives homogeneous points, which a " + std::string(geometry_name(lhs.type.geometry)) +
                   " does not take";
        // When the two maps chain the other way round (rigidmap<world, view> * projmap<view, clip>), the
        // order is the mistake: say so with the product swapped.
        const bool reversed = lhs.type.to.is_known() && rhs.type.from.is_known() && lhs.type.to == rhs.type.from;
        const std::string l = operand_text(lhs, ""), r = operand_text(rhs, "");
        hint = reversed && !l.empty() && !r.empty()
                   ? "the order is reversed: the projective map applies last, so it goes leftmost, " + r + " * " + l
                   : "apply the projective map last: it goes leftmost, projmap * map";
      }
    }
    operand_mismatch(message, lhs, rhs, range, hint, code::E_INVALID_OPERANDS);
    return std::nullopt;
  }
  Value v = builtin_call(static_cast<const ast::CallExpr*>(nullptr), builtin, *sigs, args, range, range);
  if (v.type.is_error()) return std::nullopt;
  if (node) {
    // Recorded against the operator node so the elider can rewrite `m * x`.
    std::optional<ShapeMatch> m = match_shapes(*sigs, infos);
    CallInfo info;
    info.builtin = builtin;
    info.signature = m->signature->text;
    const Geometry g = m->signature->params[1].type.geometry;
    if (builtin == "compose") info.op = GeometricOp::compose;
    else if (g == Geometry::hpoint) info.op = GeometricOp::transform_homogeneous;
    else if (m->signature->params[0].type.geometry == Geometry::projmap) info.op = GeometricOp::project;
    else if (g == Geometry::point) info.op = GeometricOp::transform_point;
    else if (m->signature->rule == BuiltinRule::normal_transform) info.op = GeometricOp::transform_normal;
    else info.op = GeometricOp::transform_vector;
    result_.calls[node] = info;
  }
  return v;
}

std::optional<Type> Checker::unify_call(const std::string& callee, const CallShape& shape, const std::vector<Value>& args,
                                        SourceRange call_range) {
  const DimensionRegistry& reg = result_.registry;
  const std::size_t dim_count = shape.dim_params ? shape.dim_params->size() : 0;
  const std::size_t space_count = shape.space_params ? shape.space_params->size() : 0;
  DimensionUnifier dims;
  for (std::size_t i = 0; i < dim_count; ++i) dims.add_variable((*shape.dim_params)[i]);
  SpaceUnifier spaces;
  for (std::size_t i = 0; i < space_count; ++i) spaces.add_variable((*shape.space_params)[i]);
  std::vector<std::size_t> equation_arg;
  const std::string fn = "'" + callee + "'";

  auto arg_error = [&](std::size_t i, const std::string& message, const std::string& hint, const char* code) {
    Diagnostic d = Diagnostic::error(args[i].range, message).with_code(code);
    add_origin_note(d, args[i]);
    if (!hint.empty()) d.with_hint(hint);
    report(std::move(d));
  };

  // A quantity kept off zero or clamped (`max(dot(n, l), 1e-4)`, `clamp(dot(n, l), 0.001, 1.0)`, saturate,
  // `max(range, 0.0001)`): a literal bound of min, max or clamp takes the dimension of what it bounds,
  // as zero does. A named plain constant (`const float eps = 1e-4;`) bounds as its literal does.
  // (In a sum the literal still needs its unit: `abs(dot(n, v)) + 0.001` of an unnormalized v.)
  const auto literal_bound = [&](const Value& a) {
    const DimSlot d = value_dimension(a.type, reg);
    return a.literal || (a.number && a.read_only && d.is_known() && d.value.is_dimensionless());
  };
  bool dimensioned_bounds = false;
  if (callee == "min" || callee == "max" || callee == "clamp")
    for (const Value& a : args) {
      const DimSlot d = value_dimension(a.type, reg);
      dimensioned_bounds = dimensioned_bounds || (!literal_bound(a) && d.is_known() && !d.value.is_dimensionless());
    }

  for (std::size_t i = 0; i < args.size(); ++i) {
    const Type& p = shape.params[i];
    const Value& a = args[i];
    if (dimensioned_bounds && literal_bound(a)) continue;
    // Spaces.
    const SpaceSlot* pslots[] = {&p.from, &p.to};
    const SpaceSlot* aslots[] = {&a.type.from, &a.type.to};
    for (int k = 0; k < 2; ++k) {
      const SpaceSlot& ps = *pslots[k];
      std::optional<SpaceTerm> at = rigid(*aslots[k]);
      if (ps.state == SpaceSlot::State::unknown || !at) continue;
      const SpaceTerm pt = ps.state == SpaceSlot::State::generic ? SpaceTerm::variable(ps.id) : *rigid(ps);
      if (!spaces.unify(pt, *at)) {
        // The space the earlier arguments fixed, for the message and the hint.
        std::optional<SpaceId> want = spaces.resolve(pt);
        const SpaceSlot expected = want ? unrigid(*want) : SpaceSlot::unknown();
        const std::string space_word = expected.state == SpaceSlot::State::known ? reg.space_name(expected.id) : "another space";
        std::string message = "argument " + std::to_string(i + 1) + " of " + fn + " has type " + name_of(a.type) + ", but " +
                              (ps.state == SpaceSlot::State::generic ? "the other arguments are in " + space_word
                                                                     : fn + " expects " + name_of(p, shape));
        const bool applying = callee == "transform" || callee == "transform_normal" || callee == "project";
        if (applying && i == 1 && args.size() == 2)
          message = "cannot apply " + name_of(args[0].type) + " to " + name_of(a.type) + ": the map takes values in " + space_word;
        std::string hint = space_hint(expected, *aslots[k]);
        if (applying && i == 1 && args.size() == 2 && a.type.from.state == SpaceSlot::State::known && a.type.from == args[0].type.to)
          hint = (a.name.empty() ? std::string("the value") : "'" + a.name + "'") + " is already in " + name_of_space(a.type.from) +
                 ", where the map leads: use it as it is, or apply the map to a value in " + space_word;
        if (callee == "compose" && args.size() == 2) {
          message = "cannot compose " + name_of(args[0].type) + " with " + name_of(args[1].type) +
                    ": the right-hand map ends in " + name_of_space(args[1].type.to) + " but the left-hand one starts in " +
                    name_of_space(args[0].type.from);
          hint = compose_hint(args[0].type, args[1].type);
        }
        arg_error(i, message, hint, code::E_SPACE_MISMATCH);
        return std::nullopt;
      }
    }
    if (orientations_clash(p.orientation, a.type.orientation)) {
      arg_error(i, "argument " + std::to_string(i + 1) + " of " + fn + " has type " + name_of(a.type) + ", but " + fn +
                       " expects " + name_of(p, shape),
                orientation_hint(a, p.orientation), code::E_ORIENTATION);
      return std::nullopt;
    }
    // Dimensions.
    if (a.zero) continue;
    const DimSlot ad = value_dimension(a.type, reg);
    std::optional<Dimension> ar = rigid(ad);
    if (!ar) continue;
    if (p.dim.state == DimSlot::State::known) {
      if (!(p.dim.value == *ar) && !cosine_as_number(p.dim, ad)) {
        arg_error(i, "argument " + std::to_string(i + 1) + " of " + fn + " has type " + name_of(a.type) + ", but " + fn +
                         " expects " + name_of(p, shape),
                  physics_hint(p.dim, ad, a.range), code::E_DIMENSION_MISMATCH);
        return std::nullopt;
      }
    } else if (p.dim.state == DimSlot::State::generic) {
      dims.add_equation(p.dim.term, DimTerm::of(*ar));
      equation_arg.push_back(i);
    }
  }

  UnifyResult solved = dims.solve();
  if (solved.status == UnifyStatus::no_solution) {
    const std::size_t i = equation_arg[solved.conflicting_equation];
    // What the earlier arguments made this parameter.
    DimensionUnifier prefix;
    for (std::size_t v = 0; v < dim_count; ++v) prefix.add_variable((*shape.dim_params)[v]);
    for (std::size_t k = 0; k < solved.conflicting_equation; ++k) {
      const std::size_t j = equation_arg[k];
      prefix.add_equation(shape.params[j].dim.term, DimTerm::of(*rigid(value_dimension(args[j].type, reg))));
    }
    UnifyResult before = prefix.solve();
    std::optional<DimSlot> expected;
    const DimTerm& term = shape.params[i].dim.term;
    bool all = true;
    Dimension value = term.constant;
    for (const auto& [v, k] : term.variables) {
      if (before.variables.size() <= v || before.variables[v].state != VariableSolution::State::determined) {
        all = false;
        break;
      }
      Checked<Dimension> p = power(before.variables[v].value, k);
      Checked<Dimension> m = p ? multiply(value, *p) : p;
      if (!m) {
        all = false;
        break;
      }
      value = *m;
    }
    if (all) expected = unrigid(value);
    const DimSlot found = value_dimension(args[i].type, reg);
    std::string message = "argument " + std::to_string(i + 1) + " of " + fn + " has type " + name_of(args[i].type);
    if (expected) {
      Type want = shape.params[i];
      want.dim = *expected;
      message += ", but the other arguments make it " + name_of(want);
    } else {
      message += ", which conflicts with the other arguments";
    }
    arg_error(i, message, expected ? physics_hint(*expected, found) : "", code::E_DIMENSION_MISMATCH);
    return std::nullopt;
  }
  if (solved.status == UnifyStatus::non_integer || solved.status == UnifyStatus::overflow) {
    std::string args_text = arguments_text(args, *this);
    Diagnostic d = Diagnostic::error(call_range, "cannot call " + fn + " with (" + args_text + "): " + dims.explain(solved, reg))
                       .with_code(solved.status == UnifyStatus::overflow ? code::E_DIMENSION_OVERFLOW : code::E_DIMENSION_ROOT);
    for (const Value& a : args) d.with_highlight(a.range);
    report(std::move(d));
    return std::nullopt;
  }

  // Substitute the solution into the result; anything not determined is `?`.
  Type result = shape.result;
  if (result.dim.state == DimSlot::State::generic) {
    bool all = true;
    Dimension value = result.dim.term.constant;
    for (const auto& [v, k] : result.dim.term.variables) {
      if (solved.variables[v].state != VariableSolution::State::determined) {
        all = false;
        break;
      }
      Checked<Dimension> p = power(solved.variables[v].value, k);
      Checked<Dimension> m = p ? multiply(value, *p) : p;
      if (!m) {
        all = false;
        break;
      }
      value = *m;
    }
    result.dim = all ? unrigid(value) : DimSlot::unknown();
  }
  for (SpaceSlot* s : {&result.from, &result.to}) {
    if (s->state != SpaceSlot::State::generic) continue;
    std::optional<SpaceId> bound = spaces.resolve(SpaceTerm::variable(s->id));
    *s = bound ? unrigid(*bound) : SpaceSlot::unknown();
  }
  return result;
}

namespace {

// How an argument reaches a parameter, for GLSL 4.00 §6.1 overload ranking.
struct Conversion {
  Scalar from, to;
  bool exact() const { return from == to; }
};

// GLSL 4.00 §6.1, for one argument (so `from` is the same on both sides): an
// exact match beats any conversion; int/uint→float beats int/uint→double.
// (Its rule "float→double beats any other conversion" never decides between
// two conversions of the same float argument.) Other pairs, e.g. int→uint
// against int→float, are neither better nor worse.
bool better_conversion(const Conversion& a, const Conversion& b) {
  if (b.exact()) return false;
  if (a.exact()) return true;
  return a.to == Scalar::float_ && b.to == Scalar::double_;
}

// The conversions a call needs to reach `f`, or nothing when `f` does not accept the arguments.
std::optional<std::vector<Conversion>> conversions_to(const Function& f, const std::vector<Value>& args) {
  if (f.params.size() != args.size()) return std::nullopt;
  std::vector<Conversion> out;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const Type& p = f.params[i];
    Type a = args[i].type;
    if (a.scalar != p.scalar) {
      // in: argument → parameter; out: parameter → argument (copied back); inout: both, so none.
      const bool fits = f.inout_params[i]  ? false
                        : f.out_params[i] ? implicitly_converts(p.scalar, a.scalar)
                                          : implicitly_converts(a.scalar, p.scalar);
      if (!fits) return std::nullopt;
    }
    out.push_back({a.scalar, p.scalar});
    a.scalar = p.scalar;
    if (!same_glsl_type(a, p) && !(p.is_array() && !a.array.empty() && p.array[0] < 0)) return std::nullopt;
    if (p.geometry != Geometry::none && a.geometry != Geometry::none && !kind_fits(a.geometry, p.geometry)) return std::nullopt;
  }
  return out;
}

// `a` is a better match than `b`: no argument converts worse, at least one better.
bool better_match(const std::vector<Conversion>& a, const std::vector<Conversion>& b) {
  bool some_better = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (better_conversion(b[i], a[i])) return false;
    some_better = some_better || better_conversion(a[i], b[i]);
  }
  return some_better;
}

std::string parameters_text(const Function& f, const DimensionRegistry& registry) {
  std::string sig;
  for (const Type& p : f.params) sig += (sig.empty() ? "" : ", ") + type_name(p, registry, &f.dim_params, &f.space_params);
  return sig;
}

}  // namespace

Value Checker::user_call(const ast::CallExpr& e, const std::vector<Function>& overloads, std::vector<Value>& args) {
  std::vector<std::pair<const Function*, std::vector<Conversion>>> viable;
  for (const Function& f : overloads)
    if (std::optional<std::vector<Conversion>> c = conversions_to(f, args)) viable.emplace_back(&f, std::move(*c));
  const Function* best = nullptr;
  for (const auto& [f, conv] : viable) {
    bool beats_all = true;
    for (const auto& [g, other] : viable)
      if (g != f && !better_match(conv, other)) beats_all = false;
    if (beats_all) best = f;
  }
  // Go to definition: the overload chosen, else one that could have been meant.
  const Function& named = best ? *best : viable.empty() ? overloads.front() : *viable.front().first;
  symbols_.use_function(e.callee, e.callee_range, named.decl, named.result);
  if (!best && viable.size() > 1) {
    Diagnostic d = Diagnostic::error(e.callee_range, "call to '" + e.callee + "(" + arguments_text(args, *this) + ")' is ambiguous")
                       .with_code(code::E_AMBIGUOUS_CALL);
    for (const auto& [f, conv] : viable)
      d.with_note(Diagnostic::note(f->decl->name_range, "candidate: " + f->name + "(" + parameters_text(*f, result_.registry) + ")"));
    d.with_hint("GLSL prefers an exact match, then float→double, then int→float over int→double");
    report(std::move(d));
    return error_value(e.range);
  }
  if (!best) {
    Diagnostic d = Diagnostic::error(e.callee_range, "no matching function for call to '" + e.callee + "(" +
                                                         arguments_text(args, *this) + ")'")
                       .with_code(code::E_NO_OVERLOAD);
    for (const Function& f : overloads)
      d.with_note(Diagnostic::note(f.decl->name_range, "candidate: " + f.name + "(" + parameters_text(f, result_.registry) + ")"));
    // One candidate: say which argument's kind keeps it out (a vector for a direction<S> parameter).
    const Function& only = overloads.front();
    for (std::size_t i = 0; overloads.size() == 1 && i < args.size() && i < only.params.size(); ++i) {
      const Geometry want = only.params[i].geometry, have = args[i].type.geometry;
      if (want == Geometry::none || have == Geometry::none || kind_fits(have, want)) continue;
      std::string why = kind_mismatch_hint(want, have);
      d.with_highlight(args[i].range);
      d.with_hint("argument " + std::to_string(i + 1) + " is " + name_of(args[i].type) + " but the parameter is " +
                  type_name(only.params[i], result_.registry, &only.dim_params, &only.space_params) + (why.empty() ? "" : ": " + why));
      break;
    }
    report(std::move(d));
    return error_value(e.range);
  }
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (best->out_params[i] && (!args[i].lvalue || args[i].read_only)) {
      report(Diagnostic::error(args[i].range, "argument " + std::to_string(i + 1) + " of '" + e.callee +
                                                  "' is an out parameter and needs a writable variable")
                 .with_code(code::E_NOT_ASSIGNABLE));
      return error_value(e.range);
    }
    if (i < best->by_reference_params.size() && best->by_reference_params[i] && !args[i].lvalue) {
      report(Diagnostic::error(args[i].range, "argument " + std::to_string(i + 1) + " of '" + e.callee +
                                                  "' is a spirv_by_reference parameter and needs a variable")
                 .with_code(code::E_NOT_ASSIGNABLE));
      return error_value(e.range);
    }
    if (i < best->literal_params.size() && best->literal_params[i] && !args[i].constant && !args[i].literal) {
      report(Diagnostic::error(args[i].range, "argument " + std::to_string(i + 1) + " of '" + e.callee +
                                                  "' is a spirv_literal parameter and needs a constant expression")
                 .with_code(code::E_NO_OVERLOAD));
      return error_value(e.range);
    }
    // Kinds: a geometric parameter takes the same kind (or an unannotated value).
  }
  CallShape shape{best->params, best->result, &best->dim_params, &best->space_params};
  std::optional<Type> result = unify_call(e.callee, shape, args, e.range);
  if (!result) return error_value(e.range);
  if (!unit_length_parameters(e.callee, *best, args)) return error_value(e.range);
  if (!homogeneous_parameters(e.callee, best->params, args)) return error_value(e.range);
  symbols_.call_result(*result);
  Value out;
  out.range = e.range;
  out.type = *result;
  return out;
}

}  // namespace safegi::detail
