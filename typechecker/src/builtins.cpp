#include "builtins.hpp"

#include <cctype>
#include <mutex>
#include <stdexcept>

namespace safegi {
namespace {

struct Entry {
  const char* name;
  BuiltinRule rule;
  const char* signature;
};

constexpr Entry kEntries[] = {
#define BUILTIN(name, rule, signature) {#name, BuiltinRule::rule, signature},
#include "builtins.def"
#undef BUILTIN
};

struct ArgumentRuleEntry {
  std::string_view name;
  ArgumentRule rule;
};

constexpr ArgumentRuleEntry kArgumentRules[] = {
#define BUILTIN_ARGUMENT_RULE(name, rule) {#name, ArgumentRule::rule},
#include "builtin_argument_rules.def"
#undef BUILTIN_ARGUMENT_RULE
};

// A tiny recursive-descent reader for the signature strings of builtins.def.
// The table is ours, so a malformed entry is a programming error (logic_error),
// caught by the unit tests that load the library.
class SignatureReader {
 public:
  SignatureReader(std::string_view text, const DimensionRegistry& registry, Signature& out)
      : text_(text), registry_(registry), sig_(out) {}

  void read() {
    skip();
    if (!at("->")) {
      sig_.params.push_back(type());
      while (eat(",")) sig_.params.push_back(type());
    }
    expect("->");
    sig_.result = type();
    skip();
    if (pos_ != text_.size()) fail("trailing text");
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::logic_error("builtins.def: " + sig_.name + " \"" + std::string(text_) + "\": " + what);
  }
  void skip() {
    while (pos_ < text_.size() && text_[pos_] == ' ') ++pos_;
  }
  bool at(std::string_view s) {
    skip();
    return text_.substr(pos_, s.size()) == s;
  }
  bool eat(std::string_view s) {
    if (!at(s)) return false;
    pos_ += s.size();
    return true;
  }
  void expect(std::string_view s) {
    if (!eat(s)) fail("expected '" + std::string(s) + "'");
  }
  std::string word() {
    skip();
    std::size_t start = pos_;
    while (pos_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_')) ++pos_;
    if (start == pos_) fail("expected a name");
    return std::string(text_.substr(start, pos_ - start));
  }
  int integer() {
    skip();
    bool negative = eat("-");
    std::size_t start = pos_;
    while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    if (start == pos_) fail("expected an integer");
    int v = std::stoi(std::string(text_.substr(start, pos_ - start)));
    return negative ? -v : v;
  }

  std::uint32_t dim_var(const std::string& name) {
    for (std::size_t i = 0; i < sig_.dim_params.size(); ++i)
      if (sig_.dim_params[i] == name) return static_cast<std::uint32_t>(i);
    sig_.dim_params.push_back(name);
    return static_cast<std::uint32_t>(sig_.dim_params.size() - 1);
  }
  std::uint32_t space_var(const std::string& name) {
    for (std::size_t i = 0; i < sig_.space_params.size(); ++i)
      if (sig_.space_params[i] == name) return static_cast<std::uint32_t>(i);
    sig_.space_params.push_back(name);
    return static_cast<std::uint32_t>(sig_.space_params.size() - 1);
  }

  // dim := factor (("*" | "/") factor)* ; factor := (name | "1") ["^" int]
  DimSlot dimension() {
    DimTerm term;
    bool unknown = false;
    int sign = 1;
    for (;;) {
      std::string name;
      if (eat("1")) name = "1";
      else name = word();
      int exponent = eat("^") ? integer() : 1;
      exponent *= sign;
      if (name == "D" || name == "E") {
        term.variables.push_back({dim_var(name), exponent});
      } else if (name != "1") {
        std::optional<Dimension> d = registry_.find_dimension(name);
        if (!d) {
          unknown = true;
        } else {
          Checked<Dimension> p = power(*d, exponent);
          Checked<Dimension> m = p ? multiply(term.constant, *p) : p;
          if (!m) fail("dimension overflow");
          term.constant = *m;
        }
      }
      if (eat("*")) sign = 1;
      else if (eat("/")) sign = -1;
      else break;
    }
    if (unknown) return DimSlot::unknown();
    if (term.variables.empty()) return DimSlot::known(term.constant);
    return DimSlot::generic(term);
  }

  SigType type() {
    SigType t;
    if (eat("out ")) t.is_out = true;
    else if (eat("inout ")) t.is_out = true;
    const std::string w = word();
    numeric_word(w, t);
    if (eat("<")) {
      if (t.type.geometry != Geometry::none || t.any_geometric) geometric_args(t);
      else t.type.dim = dimension();
      expect(">");
    } else if (t.type.geometry != Geometry::none) {
      fail("a geometric type needs its spaces");
    }
    return t;
  }

  void geometric_args(SigType& t) {
    Geometry g = t.type.geometry;
    if (g == Geometry::spectrum) {
      t.type.dim = dimension();
      return;
    }
    t.type.from = SpaceSlot::generic(space_var(word()));
    if (is_map(g)) {
      expect(",");
      t.type.to = SpaceSlot::generic(space_var(word()));
    } else if ((g == Geometry::vector || t.any_geometric) && eat(",")) {
      t.type.dim = dimension();
    }
    if (g == Geometry::vector && t.type.dim.state == DimSlot::State::unknown) {
      if (std::optional<Dimension> length = registry_.find_dimension("length")) t.type.dim = DimSlot::known(*length);
    }
    if (g == Geometry::point) {
      if (std::optional<Dimension> length = registry_.find_dimension("length")) t.type.dim = DimSlot::known(*length);
    }
    if (g == Geometry::direction || g == Geometry::normal) t.type.dim = DimSlot::known(Dimension{});
  }

  // `w` is `head`, one family letter, then `tail` (genF, matDsq, ...): no
  // temporaries, since every builtin's signature is read at start-up.
  static bool family_word(std::string_view w, std::string_view head, char family, std::string_view tail = {}) {
    return w.size() == head.size() + 1 + tail.size() && w.substr(0, head.size()) == head && w[head.size()] == family &&
           w.substr(head.size() + 1) == tail;
  }

  void numeric_word(const std::string& w, SigType& t) {
    static const struct {
      char letter;
      Scalar scalar;
    } kFamilies[] = {{'F', Scalar::float_}, {'D', Scalar::double_}, {'I', Scalar::int_}, {'U', Scalar::uint_}, {'B', Scalar::bool_}};
    for (const auto& f : kFamilies) {
      if (family_word(w, "gen", f.letter)) {
        t.size = SizeClass::gen;
        t.type = Type::scalar_of(f.scalar);
        return;
      }
      if (family_word(w, "vec", f.letter)) {
        t.size = SizeClass::vec;
        t.type = Type::vector_of(f.scalar, 2);
        return;
      }
    }
    // Matrix words: float (F) and double (D) matrices and their columns/rows.
    for (const auto& f : {kFamilies[0], kFamilies[1]}) {
      const char x = f.letter;
      if (family_word(w, "mat", x)) return set(t, SizeClass::mat, Type::matrix_of(f.scalar, 2, 2));
      if (family_word(w, "mat", x, "T")) return set(t, SizeClass::mat_transposed, Type::matrix_of(f.scalar, 2, 2));
      if (family_word(w, "mat", x, "sq")) return set(t, SizeClass::mat_square, Type::matrix_of(f.scalar, 2, 2));
      if (family_word(w, "col", x)) return set(t, SizeClass::column, Type::vector_of(f.scalar, 2));
      if (family_word(w, "row", x)) return set(t, SizeClass::row, Type::vector_of(f.scalar, 2));
    }
    if (w == "void") return set(t, SizeClass::fixed, Type::void_type());
    if (w == "geo") {
      t.any_geometric = true;
      t.type = Type::vector_of(Scalar::float_, 3);
      return;
    }
    static const struct {
      const char* word;
      Geometry geometry;
      int size;  // vec3 or vec4 or mat4 (16)
    } kGeometric[] = {{"spectrum", Geometry::spectrum, 3}, {"point", Geometry::point, 3},   {"vector", Geometry::vector, 3},
                      {"direction", Geometry::direction, 3}, {"normal", Geometry::normal, 3}, {"hpoint", Geometry::hpoint, 4},
                      {"map", Geometry::map, 16},          {"rigidmap", Geometry::rigidmap, 16}, {"projmap", Geometry::projmap, 16}};
    for (const auto& g : kGeometric) {
      if (w == g.word) {
        t.type = g.size == 16 ? Type::matrix_of(Scalar::float_, 4, 4) : Type::vector_of(Scalar::float_, g.size);
        t.type.geometry = g.geometry;
        return;
      }
    }
    // Fixed GLSL types: float vec3 ivec2 mat4 mat3x2 ...
    static const struct {
      const char* prefix;
      Scalar scalar;
    } kVectors[] = {{"vec", Scalar::float_}, {"dvec", Scalar::double_}, {"ivec", Scalar::int_}, {"uvec", Scalar::uint_}, {"bvec", Scalar::bool_},
                    {"f16vec", Scalar::float16_}, {"i64vec", Scalar::int64_}, {"u64vec", Scalar::uint64_}};
    if (w == "float16_t") return set(t, SizeClass::fixed, Type::scalar_of(Scalar::float16_));
    if (w == "int64_t") return set(t, SizeClass::fixed, Type::scalar_of(Scalar::int64_));
    if (w == "uint64_t") return set(t, SizeClass::fixed, Type::scalar_of(Scalar::uint64_));
    if (w == "float") return set(t, SizeClass::fixed, Type::scalar_of(Scalar::float_));
    if (w == "double") return set(t, SizeClass::fixed, Type::scalar_of(Scalar::double_));
    if (w == "int") return set(t, SizeClass::fixed, Type::scalar_of(Scalar::int_));
    if (w == "uint") return set(t, SizeClass::fixed, Type::scalar_of(Scalar::uint_));
    if (w == "bool") return set(t, SizeClass::fixed, Type::scalar_of(Scalar::bool_));
    for (const auto& v : kVectors) {
      const std::string_view p = v.prefix;
      if (w.size() == p.size() + 1 && std::string_view(w).substr(0, p.size()) == p && w.back() >= '2' && w.back() <= '4')
        return set(t, SizeClass::fixed, Type::vector_of(v.scalar, w.back() - '0'));
    }
    if (w.size() == 4 && w.compare(0, 3, "mat") == 0) return set(t, SizeClass::fixed, Type::matrix_of(Scalar::float_, w[3] - '0', w[3] - '0'));
    if (w.size() == 6 && w.compare(0, 3, "mat") == 0 && w[4] == 'x')  // mat4x3: 4 columns of 3
      return set(t, SizeClass::fixed, Type::matrix_of(Scalar::float_, w[3] - '0', w[5] - '0'));
    for (const char* opaque : {"accelerationStructureEXT", "rayQueryEXT", "subpassInput", "subpassInputMS",
                               "isubpassInput", "isubpassInputMS", "usubpassInput", "usubpassInputMS", "f16subpassInput",
                               "f16subpassInputMS"}) {
      if (w != opaque) continue;
      Type o;
      o.shape = Shape::opaque;
      o.opaque = w;
      return set(t, SizeClass::fixed, std::move(o));
    }
    fail("unknown type word '" + w + "'");
  }
  static void set(SigType& t, SizeClass size, Type type) {
    t.size = size;
    t.type = std::move(type);
  }

  std::string_view text_;
  const DimensionRegistry& registry_;
  Signature& sig_;
  std::size_t pos_ = 0;
};

bool vec3_like(const Type& t) { return t.shape == Shape::vector && t.rows == 3 && t.scalar == Scalar::float_ && !t.is_array(); }

}  // namespace

BuiltinLibrary::BuiltinLibrary(const DimensionRegistry& registry) {
  for (const Entry& e : kEntries) {
    Signature sig;
    sig.name = e.name;
    sig.rule = e.rule;
    sig.text = e.signature;
    if (!sig.text.empty()) SignatureReader(sig.text, registry, sig).read();
    by_name_[sig.name].push_back(std::move(sig));
  }
}

std::shared_ptr<const BuiltinLibrary> BuiltinLibrary::for_registry(const DimensionRegistry& registry) {
  // The signatures depend on the registry only through find_dimension(), i.e.
  // through the base names (their ids) and the derived dimensions' values.
  std::string key;
  for (const std::string& base : registry.bases()) key += base + ';';
  key += '|';
  for (const DerivedDimension& d : registry.derived()) {
    key += d.name + '=';
    for (const Factor& f : d.value.factors()) key += std::to_string(f.base) + '^' + std::to_string(f.exponent) + ',';
    key += ';';
  }
  static std::mutex mutex;
  static std::unordered_map<std::string, std::shared_ptr<const BuiltinLibrary>> cache;
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (auto it = cache.find(key); it != cache.end()) return it->second;
  }
  auto library = std::make_shared<const BuiltinLibrary>(registry);  // outside the lock: other threads go on
  std::lock_guard<std::mutex> lock(mutex);
  if (cache.size() >= 64) cache.clear();  // bounded: programs with ever new vocabularies
  return cache.emplace(std::move(key), std::move(library)).first->second;
}

const std::vector<Signature>* BuiltinLibrary::find(std::string_view name) const {
  auto it = by_name_.find(std::string(name));
  return it == by_name_.end() ? nullptr : &it->second;
}

DimSlot value_dimension(const Type& t, const DimensionRegistry& registry) {
  switch (t.geometry) {
    case Geometry::point:
      if (t.dim.state != DimSlot::State::unknown) return t.dim;
      if (std::optional<Dimension> length = registry.find_dimension("length")) return DimSlot::known(*length);
      return DimSlot::unknown();
    case Geometry::direction:
    case Geometry::normal: return DimSlot::known(Dimension{});
    case Geometry::hpoint:
    case Geometry::map:
    case Geometry::rigidmap:
    case Geometry::projmap: return DimSlot::unknown();
    default: return t.dim;
  }
}

namespace {

// Binds or checks a size variable; false when the argument's size disagrees.
bool bind(int& slot, int value) {
  if (slot == 0) slot = value;
  return slot == value;
}

// The cost of passing `arg` for `param`, or nothing when it does not fit.
std::optional<int> param_cost(const SigType& param, const ArgInfo& arg, ShapeMatch& m, int& n, int& c, int& r) {
  const Type& a = arg.type;
  const Type& p = param.type;
  if (a.is_error()) return 0;  // an erroneous argument fits anything: no cascade
  if (a.is_array()) return std::nullopt;
  // Opaque parameters (accelerationStructureEXT, rayQueryEXT) take exactly their type.
  if (p.shape == Shape::opaque) return a.shape == Shape::opaque && a.opaque == p.opaque ? std::optional<int>(0) : std::nullopt;
  int cost = 0;
  if (param.any_geometric || p.geometry != Geometry::none) {
    if (!vec3_like(a) && !(p.geometry == Geometry::hpoint && a.shape == Shape::vector && a.rows == 4) &&
        !(is_map(p.geometry) && a.shape == Shape::matrix && a.rows == 4 && a.columns == 4))
      return std::nullopt;
    if (param.any_geometric) {
      if (a.geometry != Geometry::vector && a.geometry != Geometry::direction && a.geometry != Geometry::normal)
        return std::nullopt;
    } else if (a.geometry != p.geometry) {
      // A rigidmap is a map (the exact rigid overload wins); plain vec3/mat4 is
      // consistent with any geometric kind (gradual typing), at a higher cost.
      if (kind_fits(a.geometry, p.geometry)) return cost + 1;
      if (a.geometry != Geometry::none || a.dim.is_known()) return std::nullopt;
      cost += 2;
    }
    return cost;
  }
  if (a.geometry != Geometry::none && a.geometry != Geometry::spectrum) cost += 4;  // geometry dropped
  if (a.shape == Shape::opaque || a.shape == Shape::structure || a.shape == Shape::void_) return std::nullopt;
  // A fixed `int` or `float` is the call's width when the argument has it (min(i64vec2, int64_t),
  // atomicMin(inout int64_t, int64_t)), else itself, reached by conversion (bitfieldExtract(i16, 0, 3)).
  const Scalar wide = m.width_of(p.scalar);
  const Scalar want = param.size != SizeClass::fixed || a.scalar == wide ? wide : p.scalar;
  if (param.is_out) {
    if (a.scalar != want) return std::nullopt;
  } else if (a.scalar != want) {
    if (!implicitly_converts(a.scalar, want)) return std::nullopt;
    cost += 1;
  }
  switch (param.size) {
    case SizeClass::fixed:
      if (a.shape != p.shape || a.rows != p.rows || a.columns != p.columns) return std::nullopt;
      break;
    case SizeClass::gen:
      if (a.shape != Shape::scalar && a.shape != Shape::vector) return std::nullopt;
      if (!bind(n, a.rows)) return std::nullopt;
      break;
    case SizeClass::vec:
      if (a.shape != Shape::vector || !bind(n, a.rows)) return std::nullopt;
      break;
    case SizeClass::mat:
      if (a.shape != Shape::matrix || !bind(c, a.columns) || !bind(r, a.rows)) return std::nullopt;
      break;
    case SizeClass::mat_transposed:
      if (a.shape != Shape::matrix || !bind(c, a.rows) || !bind(r, a.columns)) return std::nullopt;
      break;
    case SizeClass::mat_square:
      if (a.shape != Shape::matrix || a.rows != a.columns || !bind(c, a.columns) || !bind(r, a.rows)) return std::nullopt;
      break;
    case SizeClass::column:
      if (a.shape != Shape::vector || !bind(r, a.rows)) return std::nullopt;
      break;
    case SizeClass::row:
      if (a.shape != Shape::vector || !bind(c, a.rows)) return std::nullopt;
      break;
  }
  return cost;
}

// The widths a call's arguments ask the signatures to be tried at: as written, each
// explicit arithmetic width an argument has (float16_t; int8_t/uint8_t, 16 or 64), and
// the float and the first integer width together.
std::vector<ShapeMatch> width_variants(const std::vector<ArgInfo>& args) {
  std::vector<ShapeMatch> out(1);
  auto add = [&](ShapeMatch m) {
    for (const ShapeMatch& o : out)
      if (o.float_as == m.float_as && o.int_as == m.int_as && o.uint_as == m.uint_as) return;
    out.push_back(m);
  };
  for (const ArgInfo& a : args) {
    ShapeMatch m;
    switch (a.type.scalar) {
      case Scalar::float16_: m.float_as = Scalar::float16_; break;
      case Scalar::int8_:
      case Scalar::uint8_: m.int_as = Scalar::int8_, m.uint_as = Scalar::uint8_; break;
      case Scalar::int16_:
      case Scalar::uint16_: m.int_as = Scalar::int16_, m.uint_as = Scalar::uint16_; break;
      case Scalar::int64_:
      case Scalar::uint64_: m.int_as = Scalar::int64_, m.uint_as = Scalar::uint64_; break;
      default: continue;
    }
    add(m);
  }
  // Both at once: frexp(f16vec3, out i16vec3) (GL_AMD_gpu_shader_int16).
  ShapeMatch both;
  for (const ShapeMatch& m : out) {
    if (m.float_as != Scalar::float_) both.float_as = m.float_as;
    if (m.int_as != Scalar::int_ && both.int_as == Scalar::int_) both.int_as = m.int_as, both.uint_as = m.uint_as;
  }
  add(both);
  return out;
}

// `sig` matched at one width, or nothing.
std::optional<ShapeMatch> match_at(const Signature& sig, const std::vector<ArgInfo>& args, const ShapeMatch& width) {
  ShapeMatch m = width;
  m.signature = &sig;
  int n = 0, c = 0, r = 0;
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::optional<int> cost = param_cost(sig.params[i], args[i], m, n, c, r);
    if (!cost) return std::nullopt;
    m.cost += *cost;
  }
  m.n = n == 0 ? 1 : n;
  m.columns = c == 0 ? 2 : c;
  m.rows = r == 0 ? 2 : r;
  return m;
}

}  // namespace

std::optional<ShapeMatch> match_shapes(const std::vector<Signature>& candidates, const std::vector<ArgInfo>& args) {
  std::optional<ShapeMatch> best;
  const std::vector<ShapeMatch> widths = width_variants(args);
  for (const Signature& sig : candidates) {
    if (!has_signature(sig.rule) || sig.params.size() != args.size()) continue;
    for (const ShapeMatch& width : widths) {
      std::optional<ShapeMatch> m = match_at(sig, args, width);
      if (m && (!best || m->cost < best->cost)) best = m;
    }
  }
  return best;
}

Type instantiate_shape(const SigType& t, const ShapeMatch& m, bool result) {
  Type out = t.type;
  if (out.shape != Shape::opaque && (result || t.size != SizeClass::fixed)) out.scalar = m.width_of(out.scalar);
  switch (t.size) {
    case SizeClass::fixed: break;
    case SizeClass::gen:
      out.shape = m.n == 1 ? Shape::scalar : Shape::vector;
      out.rows = static_cast<std::uint8_t>(m.n);
      break;
    case SizeClass::vec: out.rows = static_cast<std::uint8_t>(m.n); break;
    case SizeClass::mat:
    case SizeClass::mat_square:
      out.columns = static_cast<std::uint8_t>(m.columns);
      out.rows = static_cast<std::uint8_t>(m.rows);
      break;
    case SizeClass::mat_transposed:
      out.columns = static_cast<std::uint8_t>(m.rows);
      out.rows = static_cast<std::uint8_t>(m.columns);
      break;
    case SizeClass::column: out.rows = static_cast<std::uint8_t>(m.rows); break;
    case SizeClass::row: out.rows = static_cast<std::uint8_t>(m.columns); break;
  }
  return out;
}

bool builtin_argument_rule(std::string_view name, ArgumentRule rule) {
  for (const ArgumentRuleEntry& e : kArgumentRules)
    if (e.rule == rule && e.name == name) return true;
  return false;
}

}  // namespace safegi
