// Annotation declarations (dimension, unit, space) and the resolution of
// annotated type specifiers into checker types.

#include <cmath>
#include <cstdlib>
#include <string_view>

#include "checker_impl.hpp"
#include "dim_slot.hpp"

namespace safegi::detail {
namespace {

// GLSL's scalar, vector and matrix type names, with the explicit arithmetic types'
// (GL_EXT_shader_explicit_arithmetic_types: int32_t is int, f64vec3 is dvec3, ...).
struct NumericNames {
  const char* scalar;         // the scalar's names (a second one, or nullptr)
  const char* scalar_alias;
  const char* vector_prefix;  // ...vec2..4
  const char* vector_alias;
  const char* matrix_prefix;  // ...mat2..4 and ...matCxR, or nullptr
  const char* matrix_alias;
  Scalar value;
};
constexpr NumericNames kNumericNames[] = {
    {"float", "float32_t", "vec", "f32vec", "mat", "f32mat", Scalar::float_},
    {"double", "float64_t", "dvec", "f64vec", "dmat", "f64mat", Scalar::double_},
    {"int", "int32_t", "ivec", "i32vec", nullptr, nullptr, Scalar::int_},
    {"uint", "uint32_t", "uvec", "u32vec", nullptr, nullptr, Scalar::uint_},
    {"bool", nullptr, "bvec", nullptr, nullptr, nullptr, Scalar::bool_},
    {"float16_t", nullptr, "f16vec", nullptr, "f16mat", nullptr, Scalar::float16_},
    {"int8_t", nullptr, "i8vec", nullptr, nullptr, nullptr, Scalar::int8_},
    {"uint8_t", nullptr, "u8vec", nullptr, nullptr, nullptr, Scalar::uint8_},
    {"int16_t", nullptr, "i16vec", nullptr, nullptr, nullptr, Scalar::int16_},
    {"uint16_t", nullptr, "u16vec", nullptr, nullptr, nullptr, Scalar::uint16_},
    {"int64_t", nullptr, "i64vec", nullptr, nullptr, nullptr, Scalar::int64_},
    {"uint64_t", nullptr, "u64vec", nullptr, nullptr, nullptr, Scalar::uint64_},
};

std::optional<Type> numeric_type(std::string_view name) {
  auto digit = [](char c) { return c >= '2' && c <= '4'; };
  auto after = [&](const char* prefix) -> std::optional<std::string_view> {
    if (!prefix || name.substr(0, std::char_traits<char>::length(prefix)) != prefix) return std::nullopt;
    return name.substr(std::char_traits<char>::length(prefix));
  };
  for (const NumericNames& n : kNumericNames) {
    if (name == n.scalar || (n.scalar_alias && name == n.scalar_alias)) return Type::scalar_of(n.value);
    for (const char* prefix : {n.vector_prefix, n.vector_alias})
      if (auto rest = after(prefix); rest && rest->size() == 1 && digit((*rest)[0])) return Type::vector_of(n.value, (*rest)[0] - '0');
    for (const char* prefix : {n.matrix_prefix, n.matrix_alias}) {
      auto rest = after(prefix);
      if (!rest) continue;
      if (rest->size() == 1 && digit((*rest)[0])) return Type::matrix_of(n.value, (*rest)[0] - '0', (*rest)[0] - '0');
      if (rest->size() == 3 && digit((*rest)[0]) && (*rest)[1] == 'x' && digit((*rest)[2]))
        return Type::matrix_of(n.value, (*rest)[0] - '0', (*rest)[2] - '0');
    }
  }
  return std::nullopt;
}

std::optional<Type> glsl_builtin_type(const std::string& name) {
  if (name == "void") return Type::void_type();
  if (std::optional<Type> t = numeric_type(name)) return t;
  for (const char* opaque : {"sampler", "isampler", "usampler", "image", "iimage", "uimage", "texture", "itexture",
                             "utexture", "subpassInput", "isubpassInput", "usubpassInput", "atomic_uint",
                             "f16sampler", "f16image", "f16texture", "f16subpassInput", "i64image", "u64image",
                             "accelerationStructure", "rayQuery", "hitObjectNV"}) {
    const std::string p = opaque;
    if (name.compare(0, p.size(), p) == 0) {
      Type t;
      t.shape = Shape::opaque;
      t.opaque = name;
      return t;
    }
  }
  return std::nullopt;
}

}  // namespace

void Checker::declare_dimension(const ast::DimensionDecl& d) {
  DimensionRegistry& reg = result_.registry;
  if (!d.definition) {
    if (const std::optional<BaseId> base = reg.find_base(d.name)) {
      if (reg.is_ratio_base(*base) == d.ratio) return;  // repeated identically: a header included twice
      report(Diagnostic::error(d.name_range, "dimension '" + d.name + "' is redeclared " +
                                                 (d.ratio ? "as a ratio; it was a physical base" : "as a physical base; it was a ratio"))
                 .with_code(code::E_REDECLARED));
      return;
    }
    if (!reg.add_base(d.name, d.ratio ? BaseKind::ratio : BaseKind::physical))
      report(Diagnostic::error(d.name_range, "'" + d.name + "' is already declared").with_code(code::E_REDECLARED));
    return;
  }
  std::optional<DimSlot> value = resolve_dimension(d.definition);
  if (!value || value->state != DimSlot::State::known) return;
  if (const DerivedDimension* existing = reg.find_derived(d.name)) {
    if (existing->value == value->value) return;
    report(Diagnostic::error(d.name_range, "dimension '" + d.name + "' is redefined as " +
                                               reg.format_product(value->value) + "; it was " +
                                               reg.format_product(existing->value))
               .with_code(code::E_REDECLARED));
    return;
  }
  if (!reg.add_derived(d.name, value->value))
    report(Diagnostic::error(d.name_range, "'" + d.name + "' is already declared").with_code(code::E_REDECLARED));
}

namespace {

// A unit's scale: a constant expression of literals, `+ - * /`, parentheses
// and earlier units (`unit foot : length = 12.0 * inch;`).
std::optional<double> fold_scale(const ast::Expr* e, const DimensionRegistry& reg) {
  if (const auto* lit = ast::dyn_cast<ast::LiteralExpr>(e)) {
    if (lit->literal_kind != ast::LiteralKind::Float && lit->literal_kind != ast::LiteralKind::Double &&
        lit->literal_kind != ast::LiteralKind::Int)
      return std::nullopt;
    return std::strtod(lit->spelling.c_str(), nullptr);
  }
  if (const auto* paren = ast::dyn_cast<ast::ParenExpr>(e)) return fold_scale(paren->inner, reg);
  if (const auto* id = ast::dyn_cast<ast::IdentifierExpr>(e)) {
    if (const Unit* u = reg.find_unit(id->name)) return u->scale;
    return std::nullopt;
  }
  if (const auto* u = ast::dyn_cast<ast::UnaryExpr>(e)) {
    std::optional<double> v = fold_scale(u->operand, reg);
    if (!v || (u->op != ast::UnaryOp::Minus && u->op != ast::UnaryOp::Plus)) return std::nullopt;
    return u->op == ast::UnaryOp::Minus ? -*v : *v;
  }
  if (const auto* b = ast::dyn_cast<ast::BinaryExpr>(e)) {
    std::optional<double> x = fold_scale(b->lhs, reg), y = fold_scale(b->rhs, reg);
    if (!x || !y) return std::nullopt;
    switch (b->op) {
      case ast::BinaryOp::Add: return *x + *y;
      case ast::BinaryOp::Sub: return *x - *y;
      case ast::BinaryOp::Mul: return *x * *y;
      case ast::BinaryOp::Div: return *x / *y;
      default: return std::nullopt;
    }
  }
  return std::nullopt;
}

}  // namespace

void Checker::declare_unit(const ast::UnitDecl& d) {
  std::optional<DimSlot> dim = resolve_dimension(d.dimension);
  if (!dim || dim->state != DimSlot::State::known) return;
  if (result_.registry.has_unit_factors(dim->value)) {
    report(Diagnostic::error(d.dimension->range, "a unit is declared by the dimension it measures, without a unit")
               .with_code(code::E_UNIT_SCALE)
               .with_hint("write the scale to the reference unit instead, e.g. unit foot : length = 12.0 * inch;"));
    return;
  }
  const std::optional<double> folded = fold_scale(d.scale, result_.registry);
  if (!folded || !std::isfinite(*folded) || *folded <= 0.0) {
    report(Diagnostic::error(d.scale ? d.scale->range : d.name_range,
                             folded ? "the scale of unit '" + d.name + "' must be a positive finite number"
                                    : "the scale of unit '" + d.name + "' must be a constant of literals and earlier units")
               .with_code(code::E_UNIT_SCALE)
               .with_hint("it is how many reference units one " + d.name + " is, e.g. unit centimeter : length = 0.01;"));
    return;
  }
  const double scale = *folded;
  DimensionRegistry& reg = result_.registry;
  if (const Unit* existing = reg.find_unit(d.name)) {
    // The same unit again (a shader that declared `hour` before the prelude had it) is that unit.
    if (existing->dimension != dim->value)
      report(Diagnostic::error(d.name_range, "unit '" + d.name + "' is redeclared with another dimension").with_code(code::E_REDECLARED));
    else if (!DimensionRegistry::same_scale(existing->scale, scale))
      report(Diagnostic::error(d.name_range, "unit '" + d.name + "' is redeclared with scale " +
                                                 DimensionRegistry::format_number(scale) + "; it was " +
                                                 DimensionRegistry::format_number(existing->scale))
                 .with_code(code::E_REDECLARED));
    return;
  }
  if (!reg.add_unit(d.name, dim->value, scale))
    report(Diagnostic::error(d.name_range, "'" + d.name + "' is already declared").with_code(code::E_REDECLARED));
}

void Checker::declare_space(const ast::SpaceDecl& d) {
  DimensionRegistry& reg = result_.registry;
  if (const std::optional<SpaceId> s = reg.find_space(d.name)) {
    if (reg.is_eye_space(*s) == d.eye && reg.is_frame_space(*s) == d.frame) return;  // a header included twice
    const std::string was = reg.is_eye_space(*s) ? " : eye" : reg.is_frame_space(*s) ? " : frame" : "";
    const std::string now = d.eye ? " : eye" : d.frame ? " : frame" : "";
    report(Diagnostic::error(d.name_range, "space '" + d.name + "' is redeclared as 'space " + d.name + now + ";'; it was 'space " +
                                               d.name + was + ";'")
               .with_code(code::E_REDECLARED));
    return;
  }
  if (!reg.add_space(d.name, d.eye, d.frame))
    report(Diagnostic::error(d.name_range, "'" + d.name + "' is already declared").with_code(code::E_REDECLARED));
}

std::optional<DimSlot> Checker::resolve_dimension(const ast::DimExpr* e) {
  const DimensionRegistry& reg = result_.registry;
  if (const auto* name = ast::dyn_cast<ast::DimName>(e)) {
    if (template_dims_) {
      for (std::size_t i = 0; i < template_dims_->size(); ++i)
        if ((*template_dims_)[i] == name->name) {
          symbols_.use_dimension_parameter(name->name, name->range);
          return DimSlot::generic(DimTerm::variable(static_cast<DimVarId>(i)));
        }
    }
    if (std::optional<Dimension> d = reg.find_dimension(name->name)) {
      symbols_.use_dimension(name->name, name->range, *d);
      return DimSlot::known(*d, name->name);
    }
    std::string message = "unknown dimension '" + name->name + "'";
    std::string hint;
    if (reg.find_space(name->name)) message = "'" + name->name + "' is a space, not a dimension";
    else if (reg.find_unit(name->name)) {
      const std::string measured = reg.format(reg.find_unit(name->name)->dimension);
      hint = "'" + name->name + "' is a unit; annotations name dimensions, e.g. '" + measured + "', or a dimension in a unit, '" +
             measured + " in " + name->name + "'";
    }
    else if (reg.base_count() == 0) hint = "did you forget '#include <safegi/prelude.sgl>'?";
    Diagnostic d = Diagnostic::error(e->range, message).with_code(code::E_UNKNOWN_DIMENSION);
    if (!hint.empty()) d.with_hint(hint);
    report(std::move(d));
    return std::nullopt;
  }
  if (ast::isa<ast::DimOne>(e)) return DimSlot::known(Dimension{});
  if (const auto* paren = ast::dyn_cast<ast::DimParen>(e)) return resolve_dimension(paren->inner);
  if (const auto* measured = ast::dyn_cast<ast::DimUnit>(e)) {
    // `length in centimeter`: the unit's dimension, checked against the one named.
    std::optional<DimSlot> d = resolve_dimension(measured->dimension);
    std::optional<Dimension> u = resolve_unit(measured->unit);
    if (!d || !u) return std::nullopt;
    if (d->state != DimSlot::State::known) {
      report(Diagnostic::error(measured->in_range, "a generic dimension cannot carry a unit").with_code(code::E_UNIT_DIMENSION));
      return std::nullopt;
    }
    Checked<Dimension> ref = reg.reference(*u);
    if (!ref || !(*ref == d->value)) {
      report(Diagnostic::error(measured->unit->range, reg.format_units(*u) + " measures " + (ref ? reg.format(*ref) : "?") +
                                                          ", not " + reg.format(d->value))
                 .with_code(code::E_UNIT_DIMENSION)
                 .with_highlight(measured->dimension->range));
      return std::nullopt;
    }
    // The declaration's name is kept (inv_length in kilometer⁻¹, not the first-declared pdf_length).
    const bool named = !d->spelling.empty() && reg.has_unit_factors(*u);
    return DimSlot::known(*u, named ? d->spelling + " in " + reg.format_units(*u) : d->spelling);
  }
  if (const auto* bin = ast::dyn_cast<ast::DimBinary>(e)) {
    std::optional<DimSlot> l = resolve_dimension(bin->lhs);
    std::optional<DimSlot> r = resolve_dimension(bin->rhs);
    if (!l || !r) return std::nullopt;
    std::optional<DimSlot> out = combine(*l, *r, bin->is_division ? -1 : 1);
    if (!out) report(Diagnostic::error(e->range, "dimension exponent overflows").with_code(code::E_DIMENSION_OVERFLOW));
    if (out) out->spelling.clear();
    return out;
  }
  if (const auto* pow = ast::dyn_cast<ast::DimPower>(e)) {
    std::optional<DimSlot> b = resolve_dimension(pow->base);
    if (!b) return std::nullopt;
    std::optional<DimSlot> out = raise(*b, pow->exponent);
    if (!out) report(Diagnostic::error(e->range, "dimension exponent overflows").with_code(code::E_DIMENSION_OVERFLOW));
    if (out) out->spelling.clear();
    return out;
  }
  return std::nullopt;
}

std::optional<Dimension> Checker::resolve_unit(const ast::DimExpr* e) {
  const DimensionRegistry& reg = result_.registry;
  if (const auto* name = ast::dyn_cast<ast::DimName>(e)) {
    if (const Unit* u = reg.find_unit(name->name)) return reg.measured_in(*u);
    if (std::optional<Dimension> d = reg.find_dimension(name->name)) return *d;  // its reference unit
    Diagnostic d = Diagnostic::error(e->range, reg.find_space(name->name) ? "'" + name->name + "' is a space, not a unit"
                                                                         : "unknown unit '" + name->name + "'")
                       .with_code(code::E_UNKNOWN_UNIT);
    if (!reg.find_space(name->name)) d.with_hint("declare it with its scale, e.g. 'unit " + name->name + " : length = 0.3048;'");
    report(std::move(d));
    return std::nullopt;
  }
  if (ast::isa<ast::DimOne>(e)) return Dimension{};
  if (const auto* paren = ast::dyn_cast<ast::DimParen>(e)) return resolve_unit(paren->inner);
  auto overflow = [&]() -> std::optional<Dimension> {
    report(Diagnostic::error(e->range, "unit exponent overflows").with_code(code::E_DIMENSION_OVERFLOW));
    return std::nullopt;
  };
  if (const auto* bin = ast::dyn_cast<ast::DimBinary>(e)) {
    std::optional<Dimension> l = resolve_unit(bin->lhs), r = resolve_unit(bin->rhs);
    if (!l || !r) return std::nullopt;
    Checked<Dimension> out = bin->is_division ? divide(*l, *r) : multiply(*l, *r);
    if (!out) return overflow();
    return *out;
  }
  if (const auto* pow = ast::dyn_cast<ast::DimPower>(e)) {
    std::optional<Dimension> b = resolve_unit(pow->base);
    if (!b) return std::nullopt;
    Checked<Dimension> out = power(*b, pow->exponent);
    if (!out) return overflow();
    return *out;
  }
  report(Diagnostic::error(e->range, "expected a unit").with_code(code::E_UNKNOWN_UNIT));
  return std::nullopt;
}

std::optional<long long> Checker::array_size(const ast::ArrayDim& dim) {
  if (!dim.size) return std::nullopt;
  Value v = expr(dim.size);
  validate_array_size(dim, v);
  if (v.constant) {
    if (*v.constant <= 0) {
      report(Diagnostic::error(dim.size->range, "array size must be greater than zero").with_code(code::E_ARRAY_SIZE));
      return std::nullopt;
    }
    return v.constant;
  }
  return std::nullopt;
}

std::optional<Orientation> Checker::orientation_word(const ast::Node* arg) const {
  const auto* name = ast::dyn_cast<ast::DimName>(arg);
  if (!name) return std::nullopt;
  for (Orientation o : {Orientation::away, Orientation::toward, Orientation::shaded})
    if (name->name == orientation_name(o)) return o;
  return std::nullopt;
}

bool Checker::orientation_fits(Geometry g, Orientation o, SourceRange where) {
  const bool directed = g == Geometry::vector || g == Geometry::direction;
  if (directed && o != Orientation::shaded) return true;
  if (g == Geometry::point && o == Orientation::shaded) return true;
  std::string message, hint;
  if (directed) {
    message = "'shaded' marks a point; a " + std::string(geometry_name(g)) + " points away from the shaded point or toward it";
    hint = std::string(geometry_name(g)) + "<S, away> or " + geometry_name(g) + "<S, toward>";
  } else if (g == Geometry::point) {
    message = "a point has no orientation; 'shaded' marks the point being shaded";
    hint = "point<S, shaded> for the shaded point; orient the vector from it (vector<S, away>) instead";
  } else {
    message = "'" + std::string(geometry_name(g)) + "' takes no orientation; only vectors and directions point away or toward";
  }
  Diagnostic d = Diagnostic::error(where, message).with_code(code::E_ORIENTATION);
  if (!hint.empty()) d.with_hint(hint);
  report(std::move(d));
  return false;
}

Type Checker::resolve_type(const ast::TypeSpecifier* spec, const std::vector<ast::ArrayDim>* declarator_dims) {
  if (!spec) return Type::error();
  const DimensionRegistry& reg = result_.registry;
  Type t;
  auto space_arg = [&](const ast::Node* arg, SpaceSlot& slot) -> bool {
    const auto* name = ast::dyn_cast<ast::DimName>(arg);
    if (!name) {
      report(Diagnostic::error(arg->range, "expected a space name").with_code(code::E_EXPECTED_SPACE));
      return false;
    }
    if (template_spaces_) {
      for (std::size_t i = 0; i < template_spaces_->size(); ++i)
        if ((*template_spaces_)[i] == name->name) {
          symbols_.use_space_parameter(name->name, name->range);
          slot = SpaceSlot::generic(static_cast<std::uint32_t>(i));
          return true;
        }
    }
    if (std::optional<SpaceId> s = reg.find_space(name->name)) {
      symbols_.use_space(name->name, name->range);
      slot = SpaceSlot::known(*s);
      return true;
    }
    Diagnostic d = Diagnostic::error(arg->range, reg.find_dimension(name->name)
                                                     ? "'" + name->name + "' is a dimension, not a space"
                                                     : "unknown space '" + name->name + "'")
                       .with_code(code::E_UNKNOWN_SPACE);
    if (!reg.find_dimension(name->name)) d.with_hint("declare it with 'space " + name->name + ";'");
    report(std::move(d));
    return false;
  };
  auto dim_arg = [&](const ast::Node* arg) -> std::optional<DimSlot> {
    if (const auto* e = ast::dyn_cast<ast::DimExpr>(arg)) return resolve_dimension(e);
    report(Diagnostic::error(arg->range, "expected a dimension").with_code(code::E_EXPECTED_DIMENSION));
    return std::nullopt;
  };
  std::size_t annotation_args = spec->annotation ? spec->annotation->args.size() : 0;  // without an orientation word
  auto arity = [&](std::size_t lo, std::size_t hi, const char* what) -> bool {
    const std::size_t n = annotation_args;
    if (n >= lo && n <= hi) return true;
    report(Diagnostic::error(spec->annotation->range, "'" + spec->name + "' takes " + what).with_code(code::E_ANNOTATION_ARITY));
    return false;
  };

  switch (spec->form) {
    case ast::TypeSpecifier::Form::Builtin: {
      std::optional<Type> base = glsl_builtin_type(spec->name);
      if (!base && extension_name(spec->name)) return Type::error();  // left to the driver
      if (!base) {
        report(Diagnostic::error(spec->name_range, "unknown type '" + spec->name + "'").with_code(code::E_UNKNOWN_TYPE));
        return Type::error();
      }
      t = *base;
      if (spec->annotation && t.shape == Shape::matrix && t.rows == t.columns && (t.rows == 3 || t.rows == 4) &&
          annotation_args >= 2) {
        // mat3<A, B>: a linear map from A to B; mat3<A, B, rigid>: a rotation (a frame such as TBN);
        // mat3<A, B, normal>: the normal matrix, carrying normals from A to B. mat4<…> likewise
        // (mat4<A, B> is map<A, B>; mat4<A, B, normal> an uploaded 4×4 normal matrix).
        const auto& args = spec->annotation->args;
        if (!arity(2, 3, "two spaces and optionally 'rigid' or 'normal'")) return Type::error();
        if (t.scalar != Scalar::float_) {
          report(Diagnostic::error(spec->annotation->range, "only float matrices carry maps").with_code(code::E_NOT_ANNOTATABLE));
          return Type::error();
        }
        if (!space_arg(args[0], t.from) || !space_arg(args[1], t.to)) return Type::error();
        t.geometry = Geometry::map;
        if (args.size() == 3) {
          const auto* word = ast::dyn_cast<ast::DimName>(args[2]);
          if (!word || (word->name != "rigid" && word->name != "normal")) {
            report(Diagnostic::error(args[2]->range, "expected 'rigid' or 'normal' after the spaces of a " + spec->name)
                       .with_code(code::E_ANNOTATION_ARITY));
            return Type::error();
          }
          if (word->name == "rigid") t.geometry = Geometry::rigidmap;
          else t.normal_matrix = true;
        }
        break;
      }
      if (spec->annotation) {
        // A sampler may name the space its lookup direction lives in: samplerCube<spectrum<radiance>, world>.
        if (!arity(1, t.shape == Shape::opaque ? 2 : 1, t.shape == Shape::opaque ? "a texel type and optionally a space" : "one annotation"))
          return Type::error();
        if (annotation_args == 2 && t.opaque.find("Cube") == std::string::npos) {
          report(Diagnostic::error(spec->annotation->args[1]->range, "only a cube map is looked up by a direction of a space; '" +
                                                                         spec->name + "' takes its texel type alone")
                     .with_code(code::E_ANNOTATION_ARITY));
          return Type::error();
        }
        if (annotation_args == 2 && !space_arg(spec->annotation->args[1], t.from)) return Type::error();
        const ast::Node* arg = spec->annotation->args[0];
        if (t.shape == Shape::opaque) {
          const auto* texel = ast::dyn_cast<ast::TypeSpecifier>(arg);
          if (!texel) {
            report(Diagnostic::error(arg->range, "a sampler's annotation is its texel type, e.g. " + spec->name +
                                                     "<float<length>>")
                       .with_code(code::E_EXPECTED_TEXEL));
            return Type::error();
          }
          Type texel_type = resolve_type(texel);
          if (texel_type.is_error()) return Type::error();
          t.texel = std::make_shared<const Type>(texel_type);
        } else if (t.is_numeric() && t.shape != Shape::void_) {
          std::optional<DimSlot> d = dim_arg(arg);
          if (!d) return Type::error();
          t.dim = *d;
        } else {
          report(Diagnostic::error(spec->annotation->range, "'" + spec->name + "' cannot carry a dimension")
                     .with_code(code::E_NOT_ANNOTATABLE));
          return Type::error();
        }
      }
      break;
    }
    case ast::TypeSpecifier::Form::Annotated: {
      static const struct {
        const char* word;
        Geometry geometry;
      } kWords[] = {{"spectrum", Geometry::spectrum}, {"point", Geometry::point},       {"vector", Geometry::vector},
                    {"direction", Geometry::direction}, {"normal", Geometry::normal}, {"hpoint", Geometry::hpoint},
                    {"map", Geometry::map},           {"rigidmap", Geometry::rigidmap}, {"projmap", Geometry::projmap}};
      Geometry g = Geometry::none;
      for (const auto& w : kWords)
        if (spec->name == w.word) g = w.geometry;
      if (g == Geometry::none || !spec->annotation) {
        report(Diagnostic::error(spec->name_range, "unknown type '" + spec->name + "'").with_code(code::E_UNKNOWN_TYPE));
        return Type::error();
      }
      t = is_map(g) ? Type::matrix_of(Scalar::float_, 4, 4) : Type::vector_of(Scalar::float_, g == Geometry::hpoint ? 4 : 3);
      t.geometry = g;
      const auto& args = spec->annotation->args;
      if (args.size() >= 2) {
        std::optional<Orientation> o = orientation_word(args.back());
        if (o && !orientation_fits(g, *o, args.back()->range)) return Type::error();
        if (o) {
          t.orientation = *o;
          --annotation_args;
        }
      }
      const std::optional<Dimension> length = reg.find_dimension("length");
      switch (g) {
        case Geometry::spectrum: {
          if (!arity(1, 1, "one dimension")) return Type::error();
          std::optional<DimSlot> d = dim_arg(args[0]);
          if (!d) return Type::error();
          t.dim = *d;
          break;
        }
        case Geometry::vector:
          if (!arity(1, 2, "a space and optionally a dimension")) return Type::error();
          if (!space_arg(args[0], t.from)) return Type::error();
          if (annotation_args == 2) {
            std::optional<DimSlot> d = dim_arg(args[1]);
            if (!d) return Type::error();
            t.dim = *d;
          } else if (length) {
            t.dim = DimSlot::known(*length);
          }
          break;
        case Geometry::point:
        case Geometry::direction:
        case Geometry::normal:
        case Geometry::hpoint:
          if (!arity(1, 1, "one space")) return Type::error();
          if (!space_arg(args[0], t.from)) return Type::error();
          if (g == Geometry::point && length) t.dim = DimSlot::known(*length);
          if (g == Geometry::direction || g == Geometry::normal) t.dim = DimSlot::known(Dimension{});
          break;
        default:  // maps
          if (!arity(2, 2, "two spaces")) return Type::error();
          if (!space_arg(args[0], t.from) || !space_arg(args[1], t.to)) return Type::error();
          break;
      }
      break;
    }
    case ast::TypeSpecifier::Form::Named: {
      auto it = structs_.find(spec->name);
      // gl_* struct types are the compatibility profile's state (gl_LightSourceParameters, …): left to the driver.
      if (it == structs_.end() && spec->name.rfind("gl_", 0) == 0) {
        builtin_available(spec->name, spec->name_range, false);
        return Type::error();
      }
      if (it == structs_.end() && (extension_name(spec->name) || glsl_builtin_type(spec->name))) {
        if (std::optional<Type> opaque = glsl_builtin_type(spec->name)) return *opaque;  // rayQueryEXT, accelerationStructureEXT
        return Type::error();
      }
      if (std::optional<Type> subroutine = it == structs_.end() ? subroutine_type(spec->name) : std::nullopt) {
        t = *subroutine;  // a subroutine uniform (subroutines.cpp)
        break;
      }
      if (it == structs_.end()) {
        report(Diagnostic::error(spec->name_range, "unknown type '" + spec->name + "'").with_code(code::E_UNKNOWN_TYPE));
        return Type::error();
      }
      t.shape = Shape::structure;
      t.structure = it->second;
      symbols_.use_structure(it->second, spec->name_range);
      break;
    }
    case ast::TypeSpecifier::Form::Spirv:
      // GL_EXT_spirv_intrinsics: an opaque type, the same as another spirv_type of the same arguments.
      t.shape = Shape::opaque;
      t.opaque = spec->name;
      break;
    case ast::TypeSpecifier::Form::Struct: {
      auto info = std::make_unique<StructInfo>();
      info->name = spec->struct_decl && !spec->struct_decl->name.empty() ? spec->struct_decl->name : "<anonymous struct>";
      if (spec->struct_decl) {
        for (const ast::VariableDecl* member : spec->struct_decl->members) {
          for (const ast::Declarator& d : member->declarators) {
            Type ft = resolve_type(member->type, &d.array_dims);
            result_.declarators[&d] = ft;
            info->fields.push_back({d.name, ft});
          }
        }
      }
      t.shape = Shape::structure;
      t.structure = info.get();
      if (spec->struct_decl) {
        symbols_.declare_structure(info.get(), *spec->struct_decl);
        symbols_.declare_fields(info.get(), spec->struct_decl->members);
      }
      if (spec->struct_decl && !spec->struct_decl->name.empty()) structs_[spec->struct_decl->name] = info.get();
      result_.structs.push_back(std::move(info));
      break;
    }
  }
  for (const ast::ArrayDim& d : spec->array_dims) t.array.push_back(static_cast<int>(array_size(d).value_or(-1)));
  return declarator_dims ? with_array_dims(std::move(t), *declarator_dims) : t;
}

Type Checker::with_array_dims(Type base, const std::vector<ast::ArrayDim>& outer) {
  // The declarator's dimensions are outermost: `float[3] a[2]` is float[2][3].
  std::vector<int> dims;
  for (const ast::ArrayDim& d : outer) dims.push_back(static_cast<int>(array_size(d).value_or(-1)));
  dims.insert(dims.end(), base.array.begin(), base.array.end());
  base.array = std::move(dims);
  return base;
}

}  // namespace safegi::detail
