#include "safegi/typechecker/type.hpp"

#include <algorithm>
#include <initializer_list>

namespace safegi {

const char* geometry_name(Geometry g) {
  switch (g) {
    case Geometry::none: return "";
    case Geometry::spectrum: return "spectrum";
    case Geometry::point: return "point";
    case Geometry::vector: return "vector";
    case Geometry::direction: return "direction";
    case Geometry::normal: return "normal";
    case Geometry::hpoint: return "hpoint";
    case Geometry::map: return "map";
    case Geometry::rigidmap: return "rigidmap";
    case Geometry::projmap: return "projmap";
  }
  return "";
}

const char* orientation_name(Orientation o) {
  switch (o) {
    case Orientation::none: return "";
    case Orientation::away: return "away";
    case Orientation::toward: return "toward";
    case Orientation::shaded: return "shaded";
  }
  return "";
}

Orientation flipped(Orientation o) {
  if (o == Orientation::away) return Orientation::toward;
  if (o == Orientation::toward) return Orientation::away;
  return o;
}

bool has_space(Geometry g) {
  return g == Geometry::point || g == Geometry::vector || g == Geometry::direction || g == Geometry::normal ||
         g == Geometry::hpoint || is_map(g);
}

bool is_map(Geometry g) { return g == Geometry::map || g == Geometry::rigidmap || g == Geometry::projmap; }
bool vectorish(Geometry g) { return g == Geometry::vector || g == Geometry::direction || g == Geometry::normal; }

bool kind_fits(Geometry value, Geometry wanted) {
  return value == wanted || (value == Geometry::rigidmap && wanted == Geometry::map);
}

Type Type::plain() const {
  Type t = *this;
  t.geometry = Geometry::none;
  t.dim = DimSlot::unknown();
  t.from = t.to = SpaceSlot::unknown();
  t.texel = nullptr;
  t.orientation = Orientation::none;
  t.affine = nullptr;
  t.affine_w = 0;
  t.normal_matrix = false;
  t.length_loss = LengthLoss::none;
  t.normal_multiple = false;
  return t;
}

Type Type::element() const {
  Type t = *this;
  if (!t.array.empty()) t.array.erase(t.array.begin());
  return t;
}

bool same_glsl_type(const Type& a, const Type& b) {
  return a.shape == b.shape && a.scalar == b.scalar && a.rows == b.rows && a.columns == b.columns &&
         a.opaque == b.opaque && a.structure == b.structure && a.array == b.array;
}

int scalar_bytes(Scalar s) {
  switch (s) {
    case Scalar::int8_:
    case Scalar::uint8_: return 1;
    case Scalar::int16_:
    case Scalar::uint16_:
    case Scalar::float16_: return 2;
    case Scalar::double_:
    case Scalar::int64_:
    case Scalar::uint64_: return 8;
    default: return 4;
  }
}

bool is_float_scalar(Scalar s) { return s == Scalar::float_ || s == Scalar::double_ || s == Scalar::float16_; }

bool is_integer_scalar(Scalar s) {
  switch (s) {
    case Scalar::int_:
    case Scalar::uint_:
    case Scalar::int8_:
    case Scalar::uint8_:
    case Scalar::int16_:
    case Scalar::uint16_:
    case Scalar::int64_:
    case Scalar::uint64_: return true;
    default: return false;
  }
}

namespace {

bool is_signed_integer(Scalar s) { return s == Scalar::int_ || s == Scalar::int8_ || s == Scalar::int16_ || s == Scalar::int64_; }

Scalar unsigned_twin(Scalar s) {
  switch (s) {
    case Scalar::int8_: return Scalar::uint8_;
    case Scalar::int16_: return Scalar::uint16_;
    case Scalar::int64_: return Scalar::uint64_;
    default: return Scalar::uint_;
  }
}

}  // namespace

bool implicitly_converts(Scalar from, Scalar to) {
  if (from == to) return true;
  using S = Scalar;
  auto one_of = [to](std::initializer_list<Scalar> l) { return std::find(l.begin(), l.end(), to) != l.end(); };
  switch (from) {
    case S::int8_: return one_of({S::uint8_, S::int16_, S::uint16_, S::int_, S::uint_, S::int64_, S::uint64_, S::float16_, S::float_, S::double_});
    case S::uint8_: return one_of({S::int16_, S::uint16_, S::int_, S::uint_, S::int64_, S::uint64_, S::float16_, S::float_, S::double_});
    case S::int16_: return one_of({S::uint16_, S::int_, S::uint_, S::int64_, S::uint64_, S::float16_, S::float_, S::double_});
    case S::uint16_: return one_of({S::int_, S::uint_, S::int64_, S::uint64_, S::float16_, S::float_, S::double_});
    case S::int_: return one_of({S::uint_, S::int64_, S::uint64_, S::float_, S::double_});
    case S::uint_: return one_of({S::int64_, S::uint64_, S::float_, S::double_});
    case S::int64_: return one_of({S::uint64_, S::double_});
    case S::uint64_: return to == S::double_;
    case S::float16_: return one_of({S::float_, S::double_});
    case S::float_: return to == S::double_;
    default: return false;
  }
}

std::optional<Scalar> common_scalar(Scalar a, Scalar b) {
  if (implicitly_converts(b, a)) return a;
  if (implicitly_converts(a, b)) return b;
  if (is_signed_integer(a) && is_integer_scalar(b) && !is_signed_integer(b) && scalar_bytes(a) > scalar_bytes(b)) return unsigned_twin(a);
  if (is_signed_integer(b) && is_integer_scalar(a) && !is_signed_integer(a) && scalar_bytes(b) > scalar_bytes(a)) return unsigned_twin(b);
  return std::nullopt;
}

namespace {

const char* scalar_word(Scalar s) {
  switch (s) {
    case Scalar::bool_: return "bool";
    case Scalar::int_: return "int";
    case Scalar::uint_: return "uint";
    case Scalar::float_: return "float";
    case Scalar::double_: return "double";
    case Scalar::int8_: return "int8_t";
    case Scalar::uint8_: return "uint8_t";
    case Scalar::int16_: return "int16_t";
    case Scalar::uint16_: return "uint16_t";
    case Scalar::int64_: return "int64_t";
    case Scalar::uint64_: return "uint64_t";
    case Scalar::float16_: return "float16_t";
    case Scalar::none: break;
  }
  return "?";
}

const char* vector_prefix(Scalar s) {
  switch (s) {
    case Scalar::bool_: return "b";
    case Scalar::int_: return "i";
    case Scalar::uint_: return "u";
    case Scalar::double_: return "d";
    case Scalar::int8_: return "i8";
    case Scalar::uint8_: return "u8";
    case Scalar::int16_: return "i16";
    case Scalar::uint16_: return "u16";
    case Scalar::int64_: return "i64";
    case Scalar::uint64_: return "u64";
    case Scalar::float16_: return "f16";
    default: return "";
  }
}

std::string array_suffix(const Type& t) {
  std::string out;
  for (int n : t.array) out += n < 0 ? "[]" : "[" + std::to_string(n) + "]";
  return out;
}

}  // namespace

std::string space_text(const SpaceSlot& s, const DimensionRegistry& registry,
                       const std::vector<std::string>* space_params) {
  switch (s.state) {
    case SpaceSlot::State::unknown: return "?";
    case SpaceSlot::State::known: return s.id < registry.spaces().size() ? registry.space_name(s.id) : "?";
    case SpaceSlot::State::generic:
      return space_params && s.id < space_params->size() ? (*space_params)[s.id] : "S" + std::to_string(s.id);
  }
  return "?";
}

std::string glsl_name(const Type& t) {
  std::string base;
  switch (t.shape) {
    case Shape::error: return "<error>";
    case Shape::void_: base = "void"; break;
    case Shape::scalar: base = scalar_word(t.scalar); break;
    case Shape::vector: base = std::string(vector_prefix(t.scalar)) + "vec" + std::to_string(t.rows); break;
    case Shape::matrix:
      base = std::string(vector_prefix(t.scalar)) + "mat" + std::to_string(t.columns);
      if (t.rows != t.columns) base += "x" + std::to_string(t.rows);
      break;
    case Shape::opaque: base = t.opaque; break;
    case Shape::structure: base = t.structure ? t.structure->name : "struct"; break;
  }
  return base + array_suffix(t);
}

std::string dim_name(const DimSlot& d, const DimensionRegistry& registry, const std::vector<std::string>* dim_params) {
  switch (d.state) {
    case DimSlot::State::unknown: return "?";
    case DimSlot::State::zero: return "0";
    case DimSlot::State::known: return d.spelling.empty() ? registry.format(d.value) : d.spelling;
    case DimSlot::State::generic: {
      std::string out;
      auto var_name = [&](DimVarId v) {
        return dim_params && v < dim_params->size() ? (*dim_params)[v] : "D" + std::to_string(v);
      };
      for (const auto& [v, k] : d.term.variables) {
        if (!out.empty()) out += "·";
        out += var_name(v);
        if (k != 1) out += "^" + std::to_string(k);
      }
      if (!d.term.constant.is_dimensionless()) {
        if (!out.empty()) out += "·";
        out += registry.format(d.term.constant);
      }
      return out.empty() ? "1" : out;
    }
  }
  return "?";
}

std::string type_name(const Type& t, const DimensionRegistry& registry, const std::vector<std::string>* dim_params,
                      const std::vector<std::string>* space_params) {
  if (t.shape == Shape::error) return "<error>";
  const std::string suffix = array_suffix(t);
  Type bare = t;
  bare.array.clear();
  if (t.geometry == Geometry::hpoint && (t.rows != 4 || t.weight != 1)) {
    // Components of a homogeneous point, before the divide: "vec2 of hpoint<clip>".
    Type whole = bare;
    whole.rows = 4;
    whole.shape = Shape::vector;
    whole.weight = 1;
    const std::string of = t.weight == 1 ? " of " : " carrying w^" + std::to_string(t.weight) + " of ";
    return glsl_name(bare.plain()) + of + type_name(whole, registry, dim_params, space_params) + suffix;
  }
  if (t.affine && t.shape == Shape::vector)
    return glsl_name(bare.plain()) + "(" + type_name(*t.affine, registry, dim_params, space_params) + ", " +
           (t.affine_w == 1 ? "1.0" : "0.0") + ")" + suffix;
  if (is_map(t.geometry) && t.shape == Shape::matrix && t.columns == 3) {
    const char* word = t.geometry == Geometry::rigidmap ? ", rigid" : t.normal_matrix ? ", normal" : "";
    return glsl_name(bare.plain()) + "<" + space_text(t.from, registry, space_params) + ", " + space_text(t.to, registry, space_params) +
           word + ">" + suffix;
  }
  if (t.normal_matrix && is_map(t.geometry)) {
    Type vectors = t;
    vectors.normal_matrix = false;
    return "the normal matrix of " + type_name(vectors, registry, dim_params, space_params);
  }
  if (t.geometry != Geometry::none) {
    std::string out = geometry_name(t.geometry);
    out += "<";
    if (t.geometry == Geometry::spectrum) {
      out += dim_name(t.dim, registry, dim_params);
    } else {
      out += space_text(t.from, registry, space_params);
      if (is_map(t.geometry)) out += ", " + space_text(t.to, registry, space_params);
      if (t.geometry == Geometry::vector && t.dim.state != DimSlot::State::unknown) {
        const std::optional<Dimension> length = registry.find_dimension("length");
        if (!(t.dim.is_known() && length && t.dim.value == *length))
          out += ", " + dim_name(t.dim, registry, dim_params);
      }
      // A stage input's normal points away from the shaded point without saying so: its own word.
      if (t.orientation != Orientation::none && t.geometry != Geometry::normal)
        out += std::string(", ") + orientation_name(t.orientation);
    }
    return out + ">" + suffix;
  }
  if (t.texel)
    return glsl_name(bare) + "<" + type_name(*t.texel, registry, dim_params, space_params) +
           (t.from.state == SpaceSlot::State::unknown ? "" : ", " + space_text(t.from, registry, space_params)) + ">" + suffix;
  if (t.dim.state == DimSlot::State::unknown || t.dim.state == DimSlot::State::zero ||
      (t.shape != Shape::scalar && t.shape != Shape::vector && t.shape != Shape::matrix))
    return glsl_name(t);
  return glsl_name(bare) + "<" + dim_name(t.dim, registry, dim_params) + ">" + suffix;
}

}  // namespace safegi
