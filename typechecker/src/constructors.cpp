// Constructors, casts (`float<solid_angle>(x)`) and the rule-typed built-in
// families (texture*, image*, atomic counters).

#include <algorithm>
#include <cmath>

#include "checker_impl.hpp"
#include "dim_slot.hpp"

namespace safegi::detail {

namespace {

// A 64-bit device address: a uint64_t, or a uvec2 (GL_EXT_buffer_reference_uvec2).
bool is_address(const Type& a) {
  return !a.is_array() && ((a.shape == Shape::scalar && a.scalar == Scalar::uint64_) ||
                           (a.shape == Shape::vector && a.rows == 2 && a.scalar == Scalar::uint_));
}

}  // namespace

// A buffer reference from a 64-bit address or another reference.
Value Checker::buffer_reference_constructor(const ast::CallExpr& e, const Value& out, const std::vector<Value>& args) {
  const Type& a = args.size() == 1 ? args[0].type : Type::error();
  const bool reference = a.shape == Shape::structure && a.structure->buffer_reference && !a.is_array();
  if (args.size() == 1 && (is_address(a) || reference)) {
    Value made = out;
    if (a.shape == Shape::scalar || reference) made.constant = args[0].constant;  // T(uint64_t(3)) is address 3
    return made;
  }
  report(Diagnostic::error(e.range, "a buffer reference '" + out.type.structure->name +
                                        "' is made from one 64-bit address (uint64_t or uvec2) or another reference")
             .with_code(code::E_CONSTRUCTOR));
  return error_value(e.range);
}

namespace {

// The texture a combined sampler is made from: `texture` for `sampler`, no `Shadow` (itexture2D for isampler2D).
std::string texture_of_sampler(std::string sampler) {
  sampler.replace(sampler.find("sampler"), 7, "texture");
  if (const std::size_t shadow = sampler.find("Shadow"); shadow != std::string::npos) sampler.erase(shadow, 6);
  return sampler;
}

}  // namespace

// Vulkan GLSL: sampler2D(texture2D, sampler), samplerCubeShadow(textureCube, samplerShadow), …
bool Checker::combined_sampler(const Type& t, const std::vector<Value>& args) const {
  if (args.size() != 2 || t.opaque.find("sampler") == std::string::npos) return false;
  const Type& image = args[0].type;
  const Type& sampler = args[1].type;
  if (image.shape != Shape::opaque || sampler.shape != Shape::opaque || image.is_array() || sampler.is_array()) return false;
  if (sampler.opaque != "sampler" && sampler.opaque != "samplerShadow") return false;
  return image.opaque == texture_of_sampler(t.opaque);
}

// A cast renames what SI measures as plain numbers — angle, solid angle, proj, a program's
// `dimension pixel : ratio;` — and adopts unannotated values; it may not make a length or an
// energy out of something else, or move a value between two spaces: `T<A>(e)` of the
// inverse-square law also accepted `1.0 / d * d` (= 1). A constant (`float<length>(0.5)`)
// takes what the cast gives it.
bool Checker::cast_keeps_physics(const Type& to_type, const Value& value) {
  const Type& from_type = value.type;
  const std::string what = name_of(to_type);
  if (!consistent(from_type.from, to_type.from) || !consistent(from_type.to, to_type.to)) {
    const bool maps = is_map(to_type.geometry);
    Diagnostic d = Diagnostic::error(value.range, "a cast cannot move " + name_of(from_type) + " to " + what +
                                                      ": a cast keeps the coordinates, and the spaces differ")
                       .with_code(code::E_SPACE_CAST);
    add_origin_note(d, value);
    d.with_hint(maps ? "compose or invert maps whose spaces meet (m2 * m1, inverse(m)) to get the map between these spaces"
                     : "apply a map from " + name_of_space(from_type.from) + " to " + name_of_space(to_type.from) +
                           " (m * x), or convert with 'in " + name_of_space(to_type.from) + "'");
    report(std::move(d));
    return false;
  }
  const DimensionRegistry& reg = result_.registry;
  const DimSlot to = value_dimension(to_type, reg), from = value_dimension(from_type, reg);
  if (value.zero || value.literal || value.number || !to.is_known() || !from.is_known()) return true;
  const Checked<Dimension> from_ref = reg.reference(from.value), to_ref = reg.reference(to.value);
  if (!from_ref || !to_ref) return true;
  const Checked<Dimension> change = divide(*to_ref, *from_ref);
  if (!change || reg.is_only_ratios(*change)) return true;
  // The physical part of the change: what the value lacks (or has too much of).
  std::vector<Factor> physical;
  for (const Factor& f : change->factors())
    if (!reg.is_ratio_base(f.base)) physical.push_back(f);
  const Checked<Dimension> missing = Dimension::from_factors(physical);
  std::vector<std::string> ratio_names;
  for (BaseId b = 0; b < reg.base_count(); ++b)
    if (reg.is_ratio_base(b)) ratio_names.push_back(reg.base_name(b));
  std::string ratios;
  for (std::size_t i = 0; i < ratio_names.size(); ++i)
    ratios += (i == 0 ? "" : i + 1 == ratio_names.size() ? " and " : ", ") + ratio_names[i];
  Diagnostic d = Diagnostic::error(value.range, "a cast cannot make " + name_of(from_type) + " into " + what + ": it would multiply " +
                                                    reg.format(from.value) + " by " + reg.format_product(*missing) +
                                                    ", and a cast may change only ratio dimensions" +
                                                    (ratios.empty() ? std::string() : " (" + ratios + ")"))
                     .with_code(code::E_DIMENSION_CAST);
  add_origin_note(d, value);
  std::string hint;
  // A quantity as a plain number is a count of some unit: x / meter is the length in metres.
  if (to.value.is_dimensionless() && !reg.has_unit_factors(from.value))
    for (const Unit& unit : reg.units())
      if (unit.dimension == *from_ref && DimensionRegistry::same_scale(unit.scale, 1.0)) {
        hint = "a " + reg.format(from.value) + " as a plain number is a count of its unit: divide by it, x / " + unit.name;
        break;
      }
  if (hint.empty()) hint = physics_hint(to, from, value.range);
  if (hint.empty())
    hint = "the value lacks a factor of " + reg.format_product(*missing) + ": check the expression (a quantity of another dimension needs the "
           "factor that gives it, not a cast)";
  d.with_hint(hint);
  report(std::move(d));
  return false;
}

Value Checker::constructor(const ast::CallExpr& e) {
  if (e.constructor_type && e.constructor_type->form == ast::TypeSpecifier::Form::Builtin && !e.constructor_type->annotation &&
      e.constructor_type->array_dims.empty()) {
    // texture2D(...) and friends: a Vulkan texture type word in newer GLSL, a built-in function in older.
    if (const std::vector<Signature>* sigs = builtins_->find(e.constructor_type->name)) {
      std::vector<Value> args;
      args.reserve(e.args.size());
      for (const ast::Expr* a : e.args) {
        args.push_back(expr(a));
        if (args.back().type.is_error()) return error_value(e.range);
      }
      return builtin_call(&e, e.constructor_type->name, *sigs, args, e.constructor_type->range, e.range);
    }
  }
  Type t = resolve_type(e.constructor_type);
  std::vector<Value> args;
  args.reserve(e.args.size());
  bool bad = t.is_error();
  for (const ast::Expr* a : e.args) {
    // A string literal (allowed by GL_EXT_debug_printf and GL_EXT_spirv_intrinsics) has no numeric
    // value: glslang 12 builds a constant of the string's address (spv.intrinsicsStringConstructorError.vert).
    if (const auto* lit = ast::dyn_cast<ast::LiteralExpr>(ast::without_parens(a)); lit && lit->literal_kind == ast::LiteralKind::String) {
      report(Diagnostic::error(a->range, "a string literal is not a constructor argument").with_code(code::E_CONSTRUCTOR));
      return error_value(e.range);
    }
    args.push_back(expr(a));
    bad = bad || args.back().type.is_error();
  }
  if (bad) return error_value(e.range);
  Value out;
  out.range = e.range;
  out.type = t;
  const auto what = [&] { return name_of(t); };  // for messages only: most constructors check
  auto fail = [&](SourceRange r, const std::string& message, const std::string& hint = {}, const char* code = code::E_CONSTRUCTOR) {
    Diagnostic d = Diagnostic::error(r, message).with_code(code);
    if (!hint.empty()) d.with_hint(hint);
    report(std::move(d));
    return error_value(e.range);
  };

  if (t.is_array()) {
    if (t.array[0] < 0) out.type.array[0] = static_cast<int>(args.size());
    else if (static_cast<std::size_t>(t.array[0]) != args.size())
      return fail(e.range, "array constructor of " + what() + " needs " + std::to_string(t.array[0]) + " arguments, found " +
                               std::to_string(args.size()));
    const Type element = out.type.element();
    for (const Value& a : args)
      if (!check_assignable(element, a, {}, "", std::nullopt, "initialize")) return error_value(e.range);
    return out;
  }
  if (t.shape == Shape::structure && t.structure->buffer_reference) return buffer_reference_constructor(e, out, args);
  if (t.shape == Shape::structure) {
    if (args.size() != t.structure->fields.size())
      return fail(e.range, "constructor of '" + t.structure->name + "' needs " + std::to_string(t.structure->fields.size()) +
                               " arguments, found " + std::to_string(args.size()));
    for (std::size_t i = 0; i < args.size(); ++i)
      if (!check_assignable(t.structure->fields[i].type, args[i], {}, t.structure->fields[i].name, std::nullopt, "initialize"))
        return error_value(e.range);
    return out;
  }
  // GL_ARB_bindless_texture: uvec2(sampler or image) and back; an ivec2 handle
  // converts implicitly to uvec2 (GLSL 4.00 int -> uint), as glslang accepts.
  const auto is_handle = [](const Type& x, bool from_int) {
    return x.shape == Shape::vector && x.rows == 2 && !x.is_array() &&
           (x.scalar == Scalar::uint_ || (from_int && x.scalar == Scalar::int_));
  };
  if (args.size() == 1 && ((is_handle(t, false) && args[0].type.shape == Shape::opaque && !args[0].type.is_array()) ||
                           (t.shape == Shape::opaque && is_handle(args[0].type, true))))
    return out;
  // A reference's address: uint64_t(reference), or uvec2(reference) (GL_EXT_buffer_reference_uvec2).
  if (args.size() == 1 && is_address(t) && args[0].type.shape == Shape::structure && args[0].type.structure->buffer_reference &&
      !args[0].type.is_array()) {
    Value address = out;
    if (t.shape == Shape::scalar) address.constant = args[0].constant;  // const uint64_t t = uint64_t(T(uint64_t(10)));
    return address;
  }
  if (t.shape == Shape::opaque && combined_sampler(t, args)) return out;
  if (t.shape == Shape::opaque && args.size() == 2 && t.opaque.find("sampler") != std::string::npos)
    return fail(e.range, what() + " is made from a " + texture_of_sampler(t.opaque) + " and a sampler or samplerShadow, not from " +
                             glsl_name(args[0].type) + " and " + glsl_name(args[1].type));
  // GL_EXT_ray_tracing: an acceleration structure from its device address.
  if (t.opaque == "accelerationStructureEXT" && args.size() == 1 && is_address(args[0].type)) return out;
  if (t.shape == Shape::opaque || t.shape == Shape::void_) return fail(e.range, "cannot construct " + what());
  if (args.empty()) return fail(e.range, "constructor of " + what() + " needs arguments");

  // GLSL: one scalar (splat / diagonal), one matrix (resize), or enough components.
  int components = 0;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const Type& a = args[i].type;
    if (a.is_array() || !(a.shape == Shape::scalar || a.shape == Shape::vector || a.shape == Shape::matrix))
      return fail(args[i].range, "cannot use " + name_of(a) + " to construct " + what());
    if (components >= t.components() && t.shape != Shape::matrix)
      return fail(args[i].range, "too many arguments to constructor of " + what());
    components += a.components();
  }
  const bool single = args.size() == 1;
  const Type& first = args[0].type;
  if (!single && components < t.components())
    return fail(e.range, "too few components to construct " + what() + " (" + std::to_string(components) + " of " +
                             std::to_string(t.components()) + ")");
  if (t.shape == Shape::matrix && !single && args.size() > 1)
    for (const Value& a : args)
      if (a.type.shape == Shape::matrix) return fail(a.range, "a matrix argument must be the only one in a matrix constructor");

  const bool annotated = t.is_annotated();
  const bool same_representation = single && first.shape == t.shape && first.rows == t.rows && first.columns == t.columns;
  out.zero = true;
  for (const Value& a : args) out.zero = out.zero && a.zero;

  if (annotated) {
    // A cast: one argument of the same representation takes the annotation, whatever it had.
    if (same_representation) {
      out.zero = args[0].zero;
      // A cast keeps the number: it may rename a dimension, not change a unit.
      const DimensionRegistry& reg = result_.registry;
      const DimSlot to = value_dimension(t, reg), from = value_dimension(first, reg);
      // A plain number (a literal, a ratio) takes the unit the cast gives it.
      const bool quantity = from.is_known() && (reg.has_unit_factors(from.value) || !from.value.is_dimensionless());
      if (!out.zero && !args[0].literal && quantity && to.is_known() &&
          !DimensionRegistry::same_scale(reg.scale(to.value), reg.scale(from.value))) {
        const double factor = reg.scale(from.value) / reg.scale(to.value);
        Diagnostic d = Diagnostic::error(args[0].range, "a cast to " + what() + " would read " + reg.format_units(from.value) +
                                                            " as " + reg.format_units(to.value) + ": a cast keeps the number")
                           .with_code(code::E_UNIT_CAST);
        add_origin_note(d, args[0]);
        d.with_hint(reg.reference(from.value) && reg.reference(to.value) && *reg.reference(from.value) == *reg.reference(to.value)
                        ? "convert instead: x in " + conversion_target(to.value) + " (× " + format_number(factor) + ")"
                        : "convert its parts to units of the same scale first: the cast would be off by × " +
                              format_number(factor));
        report(std::move(d));
        return error_value(e.range);
      }
      if (!cast_keeps_physics(t, args[0])) return error_value(e.range);
      return out;
    }
    if (std::optional<Type> frame = frame_constructor(t.plain(), args)) {  // mat3<tangent, world, rigid>(T, B, N)
      if (!consistent(frame->to, t.to))
        return fail(e.range, "the columns of " + what() + " are in " + name_of_space(frame->to) + ", not in " + name_of_space(t.to), "",
                    code::E_SPACE_MISMATCH);
      return out;
    }
    if (is_map(t.geometry)) return fail(e.range, "a " + std::string(geometry_name(t.geometry)) + " is built from one mat4");
    // Components: zero, literals and unannotated values take the annotation; others must already have it.
    const DimSlot want = value_dimension(t, result_.registry);
    for (const Value& a : args) {
      const DimSlot have = value_dimension(a.type, result_.registry);
      if (a.zero || a.literal || have.state == DimSlot::State::unknown) continue;
      if (!consistent(want, have) || (a.type.geometry != Geometry::none && a.type.geometry != Geometry::spectrum)) {
        Diagnostic d = Diagnostic::error(a.range, "a component of type " + name_of(a.type) + " cannot build " + what())
                           .with_code(code::E_DIMENSION_MISMATCH);
        add_origin_note(d, a);
        std::string hint = physics_hint(want, have);
        d.with_hint(hint.empty() ? "to reinterpret a value, cast the whole of it: " + what() + "(v)" : hint);
        report(std::move(d));
        return error_value(e.range);
      }
    }
    return out;
  }

  // Scalar conversions of constants: int(2.5) is the constant 2, float(N) the number N.
  if (single && t.shape == Shape::scalar && first.shape == Shape::scalar) {
    const std::optional<double> n = args[0].constant ? std::optional<double>(static_cast<double>(*args[0].constant)) : args[0].number;
    if (n && t.is_floating()) out.number = n;
    if (n && t.is_integer() && std::fabs(*n) < 2147483648.0 && (t.scalar == Scalar::int_ || *n >= 0.0)) {
      out.constant = static_cast<long long>(*n);
      out.number = static_cast<double>(*out.constant);
    }
  }
  // A plain GLSL constructor: the components' common dimension, if they share one.
  if (std::optional<Type> frame = frame_constructor(t, args)) {  // mat3(m), mat3(T, B, N)
    out.type = *frame;
    for (std::size_t i = 0; args.size() == 3 && i < args.size() && out.non_unit_column.empty(); ++i)
      if (args[i].type.geometry == Geometry::vector)
        out.non_unit_column = "'" + operand_text(args[i], "?") + "' (column " + std::to_string(i) + " of the frame)";
    return out;
  }
  if (t.shape == Shape::matrix) return out;  // other matrices built from parts stay unannotated
  std::optional<DimSlot> common;
  bool mixed = false;
  for (const Value& a : args) {
    if (a.zero) continue;
    DimSlot d = value_dimension(a.type, result_.registry);
    if (a.type.geometry == Geometry::hpoint || a.type.shape == Shape::matrix) d = DimSlot::unknown();
    if (!common) common = d;
    else if (!same_dimension(*common, d)) mixed = true;
  }
  // A count converted to a number is a plain number: `1.0 / (float(n) * area)` is a pdf per
  // area, not an unknown that passes for a pdf per solid angle (integers carry no annotation).
  const bool counts = t.is_floating() && std::all_of(args.begin(), args.end(), [](const Value& a) {
                        return a.type.is_integer() || a.type.scalar == Scalar::bool_;
                      });
  if (counts && !out.zero) {
    out.type.dim = DimSlot::known(Dimension{});
  } else if (common && !mixed && common->state != DimSlot::State::unknown) {
    out.type.dim = *common;
    out.type.dim.spelling.clear();
  } else if (out.zero) {
    out.type.dim = DimSlot::zero();
  }
  remember_affine_part(out.type, args);
  // vec4(x, w) is x where a map meets it: a mistake there points at where x got its kind
  // (`vec3 tangent = skinnedNormal;` makes the tangent a normal).
  if (out.type.affine && args[0].origin) {
    out.origin = args[0].origin;
    out.origin->type = out.type.affine;
  }
  if (single && t.shape == Shape::vector && t.rows == 3 && t.scalar == first.scalar)
    if (std::optional<Type> part = affine_part(first, "xyz")) out.type = *part;  // vec3(m * vec4(p, 1.0))
  // `vec3(p)` of a geometric value keeps nothing but its dimension; `vec3(spectrum)` likewise.
  // Homogeneous components stay homogeneous: vec3(h.xy, h.z) still needs the divide by w.
  if (t.shape == Shape::vector && t.is_floating())
    for (const Value& a : args)
      if (a.type.geometry == Geometry::hpoint) {
        keep_homogeneous(out.type, a.type);
        break;
      }
  return out;
}

Value Checker::rule_call(const ast::CallExpr* node, const Signature& sig, std::vector<Value>& args, SourceRange call_range) {
  (void)node;
  Value out;
  out.range = call_range;
  auto no_match = [&]() {
    std::string text;
    for (const Value& a : args) text += (text.empty() ? "" : ", ") + name_of(a.type);
    report(Diagnostic::error(call_range, "no matching overload for call to '" + sig.name + "(" + text + ")'").with_code(code::E_NO_OVERLOAD));
    return error_value(call_range);
  };
  if (sig.rule == BuiltinRule::atomic_counter) {
    if (args.size() != 1 || args[0].type.opaque != "atomic_uint") return no_match();
    out.type = Type::scalar_of(Scalar::uint_);
    return out;
  }
  if (args.empty() || args[0].type.shape != Shape::opaque || args[0].type.is_array()) return no_match();
  const Type& sampler = args[0].type;
  const std::string& name = sampler.opaque;
  const bool is_image = name.find("image") != std::string::npos;
  if ((sig.rule == BuiltinRule::image) != is_image && sig.rule != BuiltinRule::texture_size && sig.rule != BuiltinRule::texture_query)
    return no_match();
  for (std::size_t i = 1; i < args.size(); ++i) {
    const bool offsets = sig.name == "textureGatherOffsets" && args[i].type.scalar == Scalar::int_;  // ivec2 offsets[4]
    if (!(args[i].type.is_numeric() || args[i].type.scalar == Scalar::bool_) || (args[i].type.is_array() && !offsets))
      return no_match();
  }
  // Texture coordinates are points of the texture: homogeneous ones need the
  // divide by w first, except in the *Proj* lookups, which divide themselves.
  if (sig.rule == BuiltinRule::texture && args.size() > 1 && args[1].type.geometry == Geometry::hpoint &&
      sig.name.find("Proj") == std::string::npos) {
    Diagnostic d = Diagnostic::error(args[1].range, "texture coordinates of type " + name_of(args[1].type) +
                                                        " are homogeneous: the perspective divide by w is missing")
                       .with_code(code::E_KIND_MISMATCH);
    add_origin_note(d, args[1]);
    d.with_hint("divide by w first (h.xy / h.w, or homogenize(h) for a point), or let " +
                std::string(sig.name.rfind("texture", 0) == 0 ? "textureProj" : "the *Proj lookup") + " divide");
    report(std::move(d));
    return error_value(call_range);
  }
  // A cube map is looked up by direction: a position there is the environment-map bug.
  if (sig.rule == BuiltinRule::texture && args.size() > 1 && args[1].type.geometry == Geometry::point &&
      name.find("Cube") != std::string::npos) {
    Diagnostic d = Diagnostic::error(args[1].range, "a cube map is looked up by direction, not by " + name_of(args[1].type) +
                                                        ": a point is a position")
                       .with_code(code::E_POINT_ARITHMETIC);
    add_origin_note(d, args[1]);
    d.with_hint("look up the direction towards what is seen, e.g. a reflected direction reflect(-wo, n), or normalize(q - p)");
    report(std::move(d));
    return error_value(call_range);
  }
  // A cube map of one space looked up by a direction of another (a world environment by an object-space normal).
  if (sig.rule == BuiltinRule::texture && args.size() > 1 && sampler.from.state == SpaceSlot::State::known &&
      args[1].type.from.state == SpaceSlot::State::known && !(sampler.from == args[1].type.from)) {
    Diagnostic d = Diagnostic::error(args[1].range, "cannot look up " + name_of(sampler) + " by " + name_of(args[1].type) +
                                                        ": the map is indexed by directions in " + name_of_space(sampler.from))
                       .with_code(code::E_SPACE_MISMATCH);
    add_origin_note(d, args[1]);
    d.with_hint(space_hint(sampler.from, args[1].type.from));
    report(std::move(d));
    return error_value(call_range);
  }
  // isampler2D: int; u64image2D (GL_EXT_shader_image_int64): uint64_t; f16sampler2D (GL_AMD_gpu_shader_half_float_fetch): float16_t.
  const bool wide = name.compare(1, 2, "64") == 0 || name.compare(1, 2, "16") == 0;
  const Scalar texel_scalar = name[0] == 'i' ? (wide ? Scalar::int64_ : Scalar::int_)
                              : name[0] == 'u' ? (wide ? Scalar::uint64_ : Scalar::uint_)
                              : name[0] == 'f' && wide ? Scalar::float16_ : Scalar::float_;
  switch (sig.rule) {
    case BuiltinRule::texture: {
      const bool shadow = name.find("Shadow") != std::string::npos;
      const bool gather = sig.name.rfind("textureGather", 0) == 0;
      const bool legacy_shadow = sig.name.rfind("shadow", 0) == 0;  // shadow2D(...) and friends return vec4 (GLSL 1.10)
      out.type = (shadow && !gather && !legacy_shadow) ? Type::scalar_of(texel_scalar) : Type::vector_of(texel_scalar, 4);
      if (sampler.texel) out.type.dim = value_dimension(*sampler.texel, result_.registry);
      out.type.dim.spelling = sampler.texel ? sampler.texel->dim.spelling : std::string();
      // A G-buffer of normals, directions or positions: the texel's xyz is that kind in that space.
      if (const Type* texel = sampler.texel.get(); texel && out.type.rows == 4 && texel->rows == 3 &&
                                                     (texel->geometry == Geometry::point || vectorish(texel->geometry))) {
        out.type.affine = sampler.texel;
        out.type.affine_w = texel->geometry == Geometry::point ? 1 : 0;
        // A filtered lookup blends neighbouring texels (and 8-bit storage rounds them): the normal it gives
        // is shorter than 1 until normalize(), as an interpolated one is. texelFetch reads one texel as stored.
        // A normal texel is the surface's own normal at the pixel looked up: it points away from that point.
        if (texel->geometry == Geometry::normal) {
          Type stored = *texel;
          stored.orientation = Orientation::away;
          if (sig.name.rfind("texelFetch", 0) != 0) stored.length_loss = Type::LengthLoss::filtered;
          out.type.affine = std::make_shared<const Type>(stored);
        }
      }
      return out;
    }
    case BuiltinRule::texture_size: {
      const int n = name.find("Cube") != std::string::npos && name.find("Array") == std::string::npos ? 2 : [&] {
        if (name.find("1DArray") != std::string::npos) return 2;
        if (name.find("2DArray") != std::string::npos || name.find("CubeArray") != std::string::npos ||
            name.find("2DMSArray") != std::string::npos || name.find("3D") != std::string::npos)
          return 3;
        if (name.find("1D") != std::string::npos || name.find("Buffer") != std::string::npos) return 1;
        return 2;
      }();
      out.type = Type::vector_of(Scalar::int_, n);
      return out;
    }
    case BuiltinRule::texture_query:
      out.type = sig.name == "textureQueryLod" || sig.name == "textureQueryLOD" ? Type::vector_of(Scalar::float_, 2) : Type::scalar_of(Scalar::int_);
      return out;
    case BuiltinRule::image:
      if (sig.name == "imageStore" || sig.name == "imageAtomicStore") out.type = Type::void_type();
      else if (sig.name == "imageLoad") out.type = Type::vector_of(texel_scalar, 4);
      else out.type = Type::scalar_of(texel_scalar);  // imageAtomicExchange (GLSL 4.50), imageAtomicAdd (GL_EXT_shader_atomic_float) of a float image: float
      if (sampler.texel && sig.name == "imageLoad") out.type.dim = value_dimension(*sampler.texel, result_.registry);
      return out;
    default: return no_match();
  }
}

}  // namespace safegi::detail
