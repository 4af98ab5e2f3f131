// Layout qualifiers (GLSL 4.60 §4.4, GL_ARB_enhanced_layouts, the
// geometry, tessellation and compute layouts): which declaration each
// identifier applies to in which stage, their values, the stage-wide values
// every declaration must agree on, explicit block offsets and alignments,
// transform-feedback offsets and strides, components, and overlapping
// input/output locations.

#include <algorithm>
#include <cstring>
#include <iterator>
#include <string>

#include "checker_impl.hpp"
#include "validation.hpp"

namespace safegi::detail {
namespace {

const VersionGate kSeveralLayouts{420, 310, {"GL_ARB_shading_language_420pack", "GL_ARB_enhanced_layouts"}};
const VersionGate kRepeatedLayoutIds{440, 310, {"GL_ARB_enhanced_layouts"}};
const VersionGate kAttribLocations{330, 300, {"GL_ARB_explicit_attrib_location", "GL_ARB_separate_shader_objects"}};
const VersionGate kVaryingLocations{410, 310, {"GL_ARB_separate_shader_objects", "GL_EXT_separate_shader_objects"}};
const VersionGate kUniformLocations{430, 310, {"GL_ARB_explicit_uniform_location"}};
const VersionGate kBlockLocations{440, 320, {"GL_ARB_enhanced_layouts", "GL_EXT_shader_io_blocks", "GL_OES_shader_io_blocks"}};

// glslang's default resource limits (what its tests and piglit's relative sizes assume).
constexpr long long kMaxTransformFeedbackBuffers = 4;
constexpr long long kMaxTransformFeedbackBytes = 64 * 4;  // gl_MaxTransformFeedbackInterleavedComponents * 4

// Identifiers that only a declaration of their own (`layout(points) in;`)
// takes, with the stages and the storage they belong to.
struct StageLayout {
  const char* id;
  const char* stages;  // stage letters (validation.hpp)
  const char* storage;
  const char* agreement;  // the stage-wide value it sets ("" when none)
};

constexpr StageLayout kStageLayouts[] = {
    {"points", "g", "in", "input primitive"},       {"lines", "g", "in", "input primitive"},
    {"lines_adjacency", "g", "in", "input primitive"}, {"triangles", "ge", "in", "input primitive"},
    {"triangles_adjacency", "g", "in", "input primitive"}, {"invocations", "g", "in", "invocations"},
    {"line_strip", "g", "out", "output primitive"}, {"triangle_strip", "g", "out", "output primitive"},
    {"max_vertices", "gm", "out", "max_vertices"},  {"vertices", "c", "out", "vertices"},
    {"quads", "e", "in", "input primitive"},        {"isolines", "e", "in", "input primitive"},
    {"equal_spacing", "e", "in", "spacing"},        {"fractional_even_spacing", "e", "in", "spacing"},
    {"fractional_odd_spacing", "e", "in", "spacing"}, {"cw", "e", "in", "ordering"},
    {"ccw", "e", "in", "ordering"},                 {"point_mode", "e", "in", ""},
    {"local_size_x", "xtm", "in", "local_size_x"},  {"local_size_y", "xtm", "in", "local_size_y"},
    {"local_size_z", "xtm", "in", "local_size_z"},  {"local_size_variable", "x", "in", ""},
    {"local_size_x_id", "xtm", "in", ""},           {"local_size_y_id", "xtm", "in", ""},
    {"local_size_z_id", "xtm", "in", ""},
    // Mesh shaders' output primitives (GL_EXT_mesh_shader): `layout(triangles, max_vertices = 64, max_primitives = 126) out;`
    {"max_primitives", "m", "out", "max_primitives"},
    {"early_fragment_tests", "f", "in", ""},        {"post_depth_coverage", "f", "in", ""},
    {"pixel_interlock_ordered", "f", "in", "interlock"}, {"pixel_interlock_unordered", "f", "in", "interlock"},
    {"sample_interlock_ordered", "f", "in", "interlock"}, {"sample_interlock_unordered", "f", "in", "interlock"},
};

// Output primitives of the identifiers that also name an input primitive:
// `points` of geometry shaders, and `points`, `lines`, `triangles` of mesh shaders.
constexpr StageLayout kOutputPrimitives[] = {
    {"points", "gm", "out", "output primitive"}, {"lines", "m", "out", "output primitive"},
    {"triangles", "m", "out", "output primitive"}};

const StageLayout* stage_layout(std::string_view id, std::string_view storage) {
  if (storage == "out")
    for (const StageLayout& s : kOutputPrimitives)
      if (id == s.id) return &s;
  for (const StageLayout& s : kStageLayouts)
    if (id == s.id) return &s;
  return nullptr;
}

// The row of kStageLayouts named `id`.
long long layout_row(std::string_view id) {
  for (std::size_t i = 0; i < std::size(kStageLayouts); ++i)
    if (id == kStageLayouts[i].id) return static_cast<long long>(i);
  return 0;
}

bool takes_value(std::string_view id) {
  for (const char* v : {"location", "component", "index", "binding", "offset", "align", "xfb_buffer", "xfb_offset",
                        "xfb_stride", "stream", "max_vertices", "invocations", "vertices", "local_size_x", "local_size_y",
                        "local_size_z", "max_primitives", "local_size_x_id", "local_size_y_id", "local_size_z_id",
                        "constant_id", "set", "input_attachment_index", "buffer_reference_align"})
    if (id == v) return true;
  return false;
}

// Values that must be positive, not just non-negative.
bool positive_value(std::string_view id) {
  // local_size_x_id names a specialization constant: 0 is an id like any other.
  const bool size = id.rfind("local_size_", 0) == 0 && id.substr(id.size() - 3) != "_id";
  return id == "max_vertices" ? false : id == "invocations" || id == "vertices" || size;
}

// Input/output locations a type takes (GLSL 4.60 §4.4.1): dvec3/dvec4 two, a matrix one per column, arrays and structs the sum.
long long location_slots(const Type& t) {
  long long count = 1;
  for (int n : t.array) count *= std::max(n, 1);
  Type e = t;
  e.array.clear();
  long long per = 1;
  if (e.shape == Shape::structure && e.structure && !e.structure->buffer_reference) {
    per = 0;
    for (const StructField& f : e.structure->fields) per += location_slots(f.type);
  } else if (e.shape == Shape::matrix) {
    per = e.columns * (scalar_bytes(e.scalar) == 8 && e.rows >= 3 ? 2 : 1);
  } else if (scalar_bytes(e.scalar) == 8 && e.rows >= 3) {
    per = 2;
  }
  return count * per;
}

// Bytes of one transform-feedback captured value (GLSL 4.60 §4.4.2.1): components × their size.
long long xfb_bytes(const Type& t) {
  long long count = 1;
  for (int n : t.array) count *= std::max(n, 1);
  Type e = t;
  e.array.clear();
  if (e.shape == Shape::structure && e.structure && !e.structure->buffer_reference) {
    long long sum = 0;
    for (const StructField& f : e.structure->fields) sum += xfb_bytes(f.type);
    return count * sum;
  }
  return count * e.components() * scalar_bytes(e.scalar);
}

enum class PackingRules { std140, std430, scalar };

struct Packing {
  long long align = 4, size = 4;
  long long array_stride = 0;   // an array's
  long long matrix_stride = 0;  // a matrix's, or that of the matrices an array holds
  bool known = true;            // false when a part's type is one the checker does not model (uint64_t, float16_t, ...)
};

// Base alignment and size under std140 / std430 (GLSL 4.60 §7.6.2.2) or
// scalar (GL_EXT_scalar_block_layout: everything aligns to its scalars).
Packing packing_of(const Type& t, PackingRules rules, bool row_major) {
  const long long scalar = scalar_bytes(t.scalar);
  auto round_up = [](long long v, long long a) { return (v + a - 1) / a * a; };
  if (t.is_error()) return {4, 4, 0, 0, false};
  if (t.is_array()) {
    Packing element = packing_of(t.element(), rules, row_major);
    const long long align = rules == PackingRules::std140 ? round_up(element.align, 16) : element.align;
    const long long stride = round_up(element.size, align);
    return {align, stride * std::max(t.array[0], 1), stride, element.matrix_stride, element.known};
  }
  // GL_EXT_buffer_reference: a reference is a 64-bit address, whatever it points at (maybe its own block).
  if (t.shape == Shape::structure && t.structure && t.structure->buffer_reference) return {8, 8};
  if (t.shape == Shape::matrix) {
    const int vectors = row_major ? t.rows : t.columns;
    const int length = row_major ? t.columns : t.rows;
    Type column = Type::vector_of(t.scalar, length);
    column.array = {vectors};
    const Packing columns = packing_of(column, rules, false);
    return {columns.align, columns.size, 0, columns.array_stride};
  }
  if (t.shape == Shape::structure && t.structure) {
    long long align = 0, offset = 0;
    bool known = true;
    for (const StructField& f : t.structure->fields) {
      const Packing p = packing_of(f.type, rules, row_major);
      align = std::max(align, p.align);
      offset = round_up(offset, p.align) + p.size;
      known = known && p.known;
    }
    if (rules == PackingRules::std140) align = round_up(std::max<long long>(align, 1), 16);
    align = std::max<long long>(align, 1);
    return {align, round_up(offset, align), 0, 0, known};
  }
  if (t.shape == Shape::vector && rules != PackingRules::scalar) return {(t.rows == 2 ? 2 : 4) * scalar, t.rows * scalar};
  if (t.shape == Shape::vector) return {scalar, t.rows * scalar};
  return {scalar, scalar};
}

// Where the fields of a struct (the element of an array of them) lie from its start, as packing_of
// placed them; nothing for another type, or for a struct holding a type the checker does not model.
std::vector<MemberLayout> field_layouts(const Type& t, PackingRules rules, bool row_major) {
  const Type element = t.is_array() ? t.element() : t;
  if (element.shape != Shape::structure || !element.structure || element.structure->buffer_reference) return {};
  std::vector<MemberLayout> fields;
  long long offset = 0;
  for (const StructField& f : element.structure->fields) {
    const Packing p = packing_of(f.type, rules, row_major);
    if (!p.known) return {};
    offset = (offset + p.align - 1) / p.align * p.align;
    fields.push_back({offset, p.size, f.type.is_array() ? p.array_stride : 0, p.matrix_stride,
                      row_major && f.type.shape == Shape::matrix, field_layouts(f.type, rules, row_major)});
    offset += p.size;
  }
  return fields;
}

std::string storage_of(const ast::TypeQualifiers& q) {
  for (const char* s : {"in", "out", "uniform", "buffer", "shared", "attribute", "varying"})
    if (q.has(s)) return s;
  return "";
}

// The last occurrence of layout identifier `name` in `q`.
const ast::LayoutId* last_of(const ast::TypeQualifiers& q, std::string_view name) {
  const ast::LayoutId* last = nullptr;
  for (const ast::Qualifier& x : q.list)
    for (const ast::LayoutId& id : x.layout_ids)
      if (id.name == name) last = &id;
  return last;
}

}  // namespace

std::optional<long long> Checker::layout_value(const ast::LayoutId& id) {
  auto cached = validation_.layout_values.find(&id);
  if (cached != validation_.layout_values.end()) return cached->second;
  std::optional<long long>& result = validation_.layout_values[&id];
  if (!id.value) return result;
  const Value v = expr(id.value);
  if (v.type.is_error()) return result;
  if (!(v.type.shape == Shape::scalar && v.type.is_integer() && !v.type.is_array())) {
    reject(id.value->range, "the value of layout '" + id.name + "' must be a constant integer, not " + glsl_name(v.type),
           code::E_LAYOUT);
    return result;
  }
  if (const ast::Expr* part = non_constant_part(id.value)) {
    report(Diagnostic::error(id.value->range, "the value of layout '" + id.name + "' must be a constant expression")
               .with_code(code::E_LAYOUT)
               .with_highlight(part->range));
    return result;
  }
  if (v.constant && (*v.constant < 0 || (*v.constant == 0 && positive_value(id.name)))) {
    reject(id.value->range, "layout '" + id.name + "' must be " + (positive_value(id.name) ? "positive" : "non-negative") +
                                ", not " + std::to_string(*v.constant),
           code::E_LAYOUT);
    return result;
  }
  result = v.constant;
  return result;
}

// How many layout(...) a declaration has and which identifiers repeat.
static bool check_repetition(Checker& c, const ast::TypeQualifiers& q) {
  const ast::Qualifier* first_layout = nullptr;
  for (const ast::Qualifier& x : q.list) {
    if (x.kind != ast::QualifierKind::Layout) continue;
    if (first_layout && !c.allows(kSeveralLayouts)) {
      c.reject(x.range, "a second layout(...) on one declaration requires " + gate_requirement(kSeveralLayouts, c.language()->es),
               code::E_LAYOUT, "merge them: layout(a, b)");
      return false;
    }
    first_layout = first_layout ? first_layout : &x;
    for (std::size_t i = 0; i < x.layout_ids.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (x.layout_ids[i].name == x.layout_ids[j].name && !c.allows(kRepeatedLayoutIds)) {
          c.reject(x.layout_ids[i].name_range,
                   "'" + x.layout_ids[i].name + "' is given twice in one layout(...); repeating an identifier requires " +
                       gate_requirement(kRepeatedLayoutIds, c.language()->es),
                   code::E_LAYOUT);
          return false;
        }
  }
  return true;
}

namespace {

// The rules for one declaration's layout qualifiers; each check returns false
// once it reported an error (one error per declaration).
class LayoutRules {
 public:
  LayoutRules(Checker& c, const ast::TypeQualifiers& q, const LayoutSite& site)
      : c_(c), q_(q), site_(site), letter_(stage_letter(c.options_.stage)) {
    location_ = find_layout_id(q, "location");
    xfb_buffer_ = c.validation_.default_xfb_buffer;
    if (site.block)
      if (const ast::LayoutId* b = find_layout_id(site.block->qualifiers, "xfb_buffer"))
        if (std::optional<long long> v = c.layout_value(*b)) xfb_buffer_ = *v;
    if (const ast::LayoutId* b = find_layout_id(q, "xfb_buffer"))
      if (std::optional<long long> v = c.layout_value(*b)) xfb_buffer_ = *v;
  }

  void run() {
    for (const ast::Qualifier& x : q_.list)
      for (const ast::LayoutId& id : x.layout_ids)
        if (!check(id)) return;
    record_location();
  }

 private:
  bool standalone() const { return site_.kind == LayoutSite::Kind::standalone; }
  bool member() const { return site_.kind == LayoutSite::Kind::member; }
  bool in_out() const { return site_.storage == "in" || site_.storage == "out"; }
  bool fail(SourceRange where, std::string message, const char* code = code::E_LAYOUT, std::string hint = {}) {
    c_.reject(where, std::move(message), code, std::move(hint));
    return false;
  }
  // `what` is "max_vertices" or "xfb_stride of buffer 0"; `now` and `before` as they are spelled.
  bool disagree(const ast::LayoutId& id, const std::string& what, const std::string& now, const std::string& before,
                SourceRange before_range) {
    c_.report(Diagnostic::error(id.name_range, "the " + what + " is " + now + " here but " + before +
                                                   " before; every declaration must agree")
                  .with_code(code::E_LAYOUT)
                  .with_note(Diagnostic::note(before_range, "first set here")));
    return false;
  }

  bool check(const ast::LayoutId& id) {
    const std::string& name = id.name;
    if (takes_value(name) && !id.value) return fail(id.name_range, "layout '" + name + "' needs a value: '" + name + " = N'");
    const std::optional<long long> value = takes_value(name) ? c_.layout_value(id) : std::nullopt;
    // With GL_ARB_enhanced_layouts an identifier may repeat; the last one counts (GLSL 4.60 §4.4).
    if (&id != last_of(q_, name)) return true;
    if (const StageLayout* s = stage_layout(name, site_.storage)) return stage_wide(id, *s, value);
    if (name == "location") return location(id);
    if (name == "component") return component(id, value);
    if (name == "index") return index(id);
    if (name == "binding") return binding(id);
    if (name == "offset" || name == "align") return offset_or_align(id, value);
    if (name == "xfb_buffer" || name == "xfb_offset" || name == "xfb_stride") return xfb(id, value);
    if (name == "stream") return stream(id, value);
    if (name == "origin_upper_left" || name == "pixel_center_integer") return redeclaration_of(id, "gl_FragCoord");
    if (name.rfind("depth_", 0) == 0) return redeclaration_of(id, "gl_FragDepth");
    return true;  // block layouts are the parser's; other identifiers belong to extensions not modelled here
  }

  // `layout(points) in;`, `layout(max_vertices = 4) out;`, `layout(local_size_x = 8) in;`
  bool stage_wide(const ast::LayoutId& id, const StageLayout& s, const std::optional<long long>& value) {
    const std::string& name = id.name;
    if (letter_ != '*' && !std::strchr(s.stages, letter_))
      return fail(id.name_range, "layout '" + name + "' belongs to " + stage_list(s.stages) + " shaders, not to " +
                                     stage_name(c_.options_.stage) + " shaders");
    if (!standalone() || site_.storage != s.storage)
      return fail(id.name_range, "layout '" + name + "' applies only to a declaration of its own: 'layout(" + name +
                                     (takes_value(name) ? " = N" : "") + ") " + s.storage + ";'");
    if (!*s.agreement) return true;
    // Primitives agree by name (their row of kStageLayouts), the others by value.
    const bool by_value = takes_value(name);
    const long long v = by_value ? value.value_or(-1) : layout_row(s.id);
    auto [it, fresh] = c_.validation_.stage_layouts.emplace(s.agreement, std::pair{v, id.name_range});
    if (fresh || it->second.first == v || v < 0 || it->second.first < 0) return true;
    auto spelled = [&](long long x) {
      if (by_value) return std::to_string(x);
      return std::string("'") + kStageLayouts[x].id + "'";
    };
    return disagree(id, s.agreement, spelled(v), spelled(it->second.first), it->second.second);
  }

  bool location(const ast::LayoutId& id) {
    if (standalone()) return fail(id.name_range, "layout 'location' applies to a variable, not to a default declaration");
    if (site_.storage == "attribute" || site_.storage == "varying")
      return fail(id.name_range, "layout 'location' applies to 'in' and 'out' declarations, not to '" + site_.storage + "'");
    if (site_.storage == "uniform" && site_.kind == LayoutSite::Kind::block)
      return fail(id.name_range, "layout 'location' does not apply to uniform blocks");
    const bool variable = site_.kind == LayoutSite::Kind::variable;
    const bool attrib = variable && ((site_.storage == "in" && letter_ == 'v') || (site_.storage == "out" && letter_ == 'f'));
    const bool uniform = site_.storage == "uniform" || site_.storage == "buffer";
    const VersionGate& gate = uniform ? kUniformLocations : !variable ? kBlockLocations : attrib ? kAttribLocations : kVaryingLocations;
    if (!(in_out() || site_.storage == "uniform") || c_.allows(gate)) return true;
    const std::string what = site_.storage == "uniform" ? "on a uniform"
                             : !variable                ? "on a block or block member"
                             : attrib ? (letter_ == 'v' ? "on a vertex shader input" : "on a fragment shader output")
                                      : "on a shader input or output between stages";
    return fail(id.name_range, "layout 'location' " + what + " requires " + gate_requirement(gate, c_.language()->es),
                code::E_VERSION);
  }

  bool component(const ast::LayoutId& id, const std::optional<long long>& value) {
    if (!location_ && !(member() && site_.block && find_layout_id(site_.block->qualifiers, "location")))
      return fail(id.name_range, "layout 'component' needs a 'location' on the same declaration");
    const Type* t = site_.type;
    if (site_.kind == LayoutSite::Kind::block || (t && (t->shape == Shape::matrix || t->shape == Shape::structure)))
      return fail(id.name_range, "layout 'component' does not apply to a matrix, a struct or a block");
    if (!t || !value) return true;
    const Type element = t->is_array() ? t->element() : *t;
    const bool is_double = scalar_bytes(element.scalar) == 8;
    const long long width = (element.shape == Shape::vector ? element.rows : 1) * (is_double ? 2 : 1);
    if (is_double && *value % 2 != 0)
      return fail(id.value->range, "a double starts at component 0 or 2, not " + std::to_string(*value));
    if (*value + width > 4)
      return fail(id.value->range, "component " + std::to_string(*value) + " of " + glsl_name(element) +
                                       " overflows the four components of a location");
    return true;
  }

  bool index(const ast::LayoutId& id) {
    if (letter_ == 'f' && site_.storage == "out" && site_.kind == LayoutSite::Kind::variable) return true;
    return fail(id.name_range, "layout 'index' applies only to fragment shader outputs");
  }

  bool binding(const ast::LayoutId& id) {
    const Type* t = site_.type;
    const bool opaque = t && (contains_opaque(*t) || t->shape == Shape::opaque);
    const bool buffers = site_.storage == "uniform" || site_.storage == "buffer";
    const bool ok = (buffers && site_.kind == LayoutSite::Kind::block) ||
                    (site_.storage == "uniform" && site_.kind == LayoutSite::Kind::variable && opaque) ||
                    (standalone() && buffers) || (t && t->is_error());
    if (ok) return true;
    return fail(id.name_range, "layout 'binding' applies to uniform and buffer blocks, samplers, images and atomic counters");
  }

  bool offset_or_align(const ast::LayoutId& id, const std::optional<long long>& value) {
    const std::string& name = id.name;
    const bool atomic = site_.type && site_.type->shape == Shape::opaque && site_.type->opaque == "atomic_uint";
    const bool buffers = site_.storage == "uniform" || site_.storage == "buffer";
    const bool block = buffers && (member() || (name == "align" && site_.kind == LayoutSite::Kind::block));
    if (!block && !(atomic && name == "offset") && !(standalone() && name == "offset" && site_.storage == "uniform"))
      return fail(id.name_range, "layout '" + name + "' applies to members of uniform and buffer blocks" +
                                     (name == "offset" ? std::string(" and to atomic counters") : ""));
    // The parser leaves offset from 4.20 on to this check: an atomic counter's is 4.20's, any other 4.40's.
    if (const LanguageLevel* level = c_.language(); level && name == "offset" && !atomic && !level->es && level->version >= 420)
      if (std::string need = layout_id_requirement("offset", *level); !need.empty()) return fail(id.name_range, need, code::E_VERSION);
    if (name == "align" && value && (*value == 0 || (*value & (*value - 1)) != 0))
      return fail(id.value->range, "layout 'align' must be a power of two, not " + std::to_string(*value));
    return true;
  }

  std::string stride_key() const { return "xfb_stride of buffer " + std::to_string(xfb_buffer_); }

  // GLSL 4.60 §4.4.2.1 (transform feedback layouts).
  bool xfb(const ast::LayoutId& id, const std::optional<long long>& value) {
    const std::string& name = id.name;
    if (!(site_.storage == "out" && letter_ != 'f' && letter_ != 'x'))
      return fail(id.name_range, "layout '" + name + "' applies to outputs of vertex, tessellation and geometry shaders");
    if (name == "xfb_offset" && standalone())
      return fail(id.name_range, "layout 'xfb_offset' applies to a variable or block, not to a default declaration", code::E_LAYOUT,
                  "use 'xfb_buffer' or 'xfb_stride' in 'layout(...) out;'");
    if (!value) return true;
    const long long v = *value;
    if (name == "xfb_buffer") return xfb_buffer(id, v);
    if (name == "xfb_stride") return xfb_stride(id, v);
    return xfb_offset(id, v);
  }

  bool xfb_buffer(const ast::LayoutId& id, long long v) {
    if (v >= kMaxTransformFeedbackBuffers)
      return fail(id.value->range, "layout 'xfb_buffer' must be less than gl_MaxTransformFeedbackBuffers (" +
                                       std::to_string(kMaxTransformFeedbackBuffers) + ")");
    if (member() && site_.block) {
      long long block_buffer = c_.validation_.default_xfb_buffer;
      if (const ast::LayoutId* b = find_layout_id(site_.block->qualifiers, "xfb_buffer"))
        if (std::optional<long long> bv = c_.layout_value(*b)) block_buffer = *bv;
      if (v != block_buffer)
        return fail(id.value->range, "a block member's xfb_buffer " + std::to_string(v) + " contradicts its block's (" +
                                         std::to_string(block_buffer) + ")");
    }
    if (standalone()) c_.validation_.default_xfb_buffer = v;
    return true;
  }

  // Not a multiple of 4 (8 with doubles) is a link-time error to glslang (Test/link.multiUnitLayout.2.vert): not checked.
  bool xfb_stride(const ast::LayoutId& id, long long v) {
    if (v > kMaxTransformFeedbackBytes)
      return fail(id.value->range, "layout 'xfb_stride' " + std::to_string(v) +
                                       " is more than gl_MaxTransformFeedbackInterleavedComponents * 4 (" +
                                       std::to_string(kMaxTransformFeedbackBytes) + ")");
    auto [it, fresh] = c_.validation_.stage_layouts.emplace(stride_key(), std::pair{v, id.name_range});
    if (!fresh && it->second.first != v)
      return disagree(id, stride_key(), std::to_string(v), std::to_string(it->second.first), it->second.second);
    return true;
  }

  bool xfb_offset(const ast::LayoutId& id, long long v) {
    // What the offset captures: the variable, or every member of the block.
    std::vector<const Type*> captured;
    if (site_.kind == LayoutSite::Kind::block && site_.block) {
      for (const ast::VariableDecl* m : site_.block->members)
        for (const ast::Declarator& d : m->declarators)
          if (const Type* t = c_.result_.type_of(&d)) captured.push_back(t);
    } else if (site_.type) {
      captured.push_back(site_.type);
    }
    // 8 with a 64-bit scalar in it, else 4 with a 32-bit one, else 2 with a 16-bit one (glslang: no rule for 8-bit).
    int widest = 0;
    for (const Type* c : captured) widest = std::max(widest, widest_scalar_bytes(*c));
    const long long multiple = widest == 0 ? 4 : widest;
    const bool doubles =
        std::any_of(captured.begin(), captured.end(), [](const Type* t) { return contains_scalar(*t, Scalar::double_); });
    if (v % multiple != 0)
      return fail(id.value->range, "layout 'xfb_offset' must be a multiple of " + std::to_string(multiple) +
                                       (doubles ? " (the value holds a double)" : multiple == 8 ? " (the value holds a 64-bit integer)" : ""));
    long long bytes = 0;
    for (const Type* t : captured) {
      if (t->is_array() && t->array[0] < 0) return fail(id.name_range, "layout 'xfb_offset' cannot capture an unsized array");
      bytes += xfb_bytes(*t);
    }
    long long stride = kMaxTransformFeedbackBytes;
    if (auto it = c_.validation_.stage_layouts.find(stride_key()); it != c_.validation_.stage_layouts.end()) stride = it->second.first;
    if (const ast::LayoutId* s = find_layout_id(q_, "xfb_stride"))
      if (std::optional<long long> sv = c_.layout_value(*s)) stride = *sv;
    if (v + bytes > stride)
      return fail(id.value->range, "what layout 'xfb_offset' " + std::to_string(v) + " captures (" + std::to_string(bytes) +
                                       " bytes) overflows the buffer's stride of " + std::to_string(stride) + " bytes");
    return true;
  }

  bool stream(const ast::LayoutId& id, const std::optional<long long>& value) {
    if (!(letter_ == 'g' && site_.storage == "out")) return fail(id.name_range, "layout 'stream' applies only to geometry shader outputs");
    if (!member() || !site_.block || !value) return true;
    const ast::LayoutId* b = find_layout_id(site_.block->qualifiers, "stream");
    const std::optional<long long> block_stream = b ? c_.layout_value(*b) : std::optional<long long>(0);
    if (block_stream && *block_stream != *value)
      return fail(id.value->range, "a block member's stream " + std::to_string(*value) + " contradicts its block's (" +
                                       std::to_string(*block_stream) + ")");
    return true;
  }

  bool redeclaration_of(const ast::LayoutId& id, const char* builtin) {
    if (site_.kind == LayoutSite::Kind::variable && site_.name == builtin) return true;
    return fail(id.name_range, "layout '" + id.name + "' applies only to a redeclaration of " + builtin);
  }

  // Locations of inputs and outputs between stages. Vertex inputs may alias, and Mesa checks fragment outputs
  // against each other when linking (piglit's arb_explicit_attrib_location layout-10.frag compiles).
  void record_location() {
    const bool vertex_input = letter_ == 'v' && site_.storage == "in";
    const bool fragment_output = letter_ == 'f' && site_.storage == "out";
    if (!location_ || site_.kind != LayoutSite::Kind::variable || !site_.type || vertex_input || fragment_output || !in_out())
      return;
    const std::optional<long long> first = c_.layout_value(*location_);
    if (!first) return;
    Type t = *site_.type;
    // A fragment shader's `pervertexEXT in float v[3];` (GL_EXT/NV_fragment_shader_barycentric) is one value per
    // vertex of the primitive: one location, as a geometry shader's inputs (spv.fragmentShaderBarycentric2.frag).
    const bool barycentric = letter_ == 'f' && site_.storage == "in" && (q_.has("pervertexEXT") || q_.has("pervertexNV"));
    const bool per_vertex = (site_.storage == "in" && (letter_ == 'g' || letter_ == 'c' || letter_ == 'e')) ||
                            (site_.storage == "out" && (letter_ == 'c' || letter_ == 'm')) || barycentric;
    if (per_vertex && t.is_array()) t = t.element();
    // GL_NV_mesh_shader: a per-view output's next dimension is the view's (spv.meshShaderPerViewUserDefined.mesh).
    if (letter_ == 'm' && site_.storage == "out" && q_.has("perviewNV") && t.is_array()) t = t.element();
    LocationUse use;
    use.output = site_.storage == "out";
    use.first = *first;
    use.last = *first + location_slots(t) - 1;
    if (const ast::LayoutId* comp = find_layout_id(q_, "component"))
      if (std::optional<long long> v = c_.layout_value(*comp)) {
        const Type e = t.is_array() ? t.element() : t;
        use.first_component = static_cast<int>(*v);
        use.last_component = static_cast<int>(*v + (e.shape == Shape::vector ? e.rows : 1) * (scalar_bytes(e.scalar) == 8 ? 2 : 1) - 1);
      }
    use.name = site_.name;
    use.range = location_->name_range;
    for (const LocationUse& other : c_.validation_.locations) {
      if (other.output != use.output || other.last < use.first || use.last < other.first) continue;
      if (other.last_component < use.first_component || use.last_component < other.first_component) continue;
      const long long shared = std::max(other.first, use.first);
      c_.report(Diagnostic::error(location_->value ? location_->value->range : location_->name_range,
                                  "location " + std::to_string(shared) + " is already used by " +
                                      (use.output ? std::string("output '") : std::string("input '")) + other.name + "'")
                    .with_code(code::E_LAYOUT)
                    .with_note(Diagnostic::note(other.range, "'" + other.name + "' takes locations " + std::to_string(other.first) +
                                                                 (other.last > other.first ? "-" + std::to_string(other.last) : ""))));
      return;
    }
    c_.validation_.locations.push_back(std::move(use));
  }

  Checker& c_;
  const ast::TypeQualifiers& q_;
  const LayoutSite& site_;
  const char letter_;
  const ast::LayoutId* location_ = nullptr;
  long long xfb_buffer_ = 0;
};

}  // namespace

void Checker::validate_layouts(const ast::TypeQualifiers& q, const LayoutSite& site) {
  if (!check_repetition(*this, q)) return;
  LayoutRules(*this, q, site).run();
}

void Checker::validate_global_layouts(const ast::VariableDecl& d) {
  if (d.declarators.empty()) return;
  LayoutSite site;
  site.storage = storage_of(d.qualifiers);
  site.type = result_.type_of(&d.declarators.front());
  site.name = d.declarators.front().name;
  validate_layouts(d.qualifiers, site);
}

void Checker::validate_block_layouts(const ast::InterfaceBlockDecl& d) {
  LayoutSite site;
  site.kind = LayoutSite::Kind::block;
  site.storage = storage_of(d.qualifiers);
  site.name = d.block_name;
  site.block = &d;
  validate_layouts(d.qualifiers, site);
  for (const ast::VariableDecl* m : d.members) {
    if (m->declarators.empty()) continue;
    LayoutSite member = site;
    member.kind = LayoutSite::Kind::member;
    member.type = result_.type_of(&m->declarators.front());
    member.name = m->declarators.front().name;
    validate_layouts(m->qualifiers, member);
  }
  validate_block_layout(d);
}

void Checker::validate_default_layouts(const ast::QualifierDecl& d) {
  if (!d.names.empty()) return;  // `invariant gl_Position;`
  LayoutSite site;
  site.kind = LayoutSite::Kind::standalone;
  site.storage = storage_of(d.qualifiers);
  validate_layouts(d.qualifiers, site);
  for (const char* p : {"std140", "std430", "shared", "packed"}) {
    if (!find_layout_id(d.qualifiers, p)) continue;
    if (site.storage == "uniform") validation_.uniform_packing = p;
    if (site.storage == "buffer") validation_.buffer_packing = p;
  }
}

// Explicit offsets and alignments of the members of a std140/std430 block
// (GLSL 4.60 §4.4.5): each offset is a multiple of the member's base
// alignment and past the end of the member before it. Where every member is
// placed goes into CheckResult::block_layouts (the symbol table's offsets).
void Checker::validate_block_layout(const ast::InterfaceBlockDecl& d) {
  const std::string storage = storage_of(d.qualifiers);
  if (storage != "uniform" && storage != "buffer") return;
  std::string packing = storage == "uniform" ? validation_.uniform_packing : validation_.buffer_packing;
  // GL_KHR_vulkan_glsl: a push-constant block is std430 unless it says otherwise.
  if (vulkan_glsl(language()) && find_layout_id(d.qualifiers, "push_constant")) packing = "std430";
  for (const char* p : {"std140", "std430", "shared", "packed", "scalar"})
    if (find_layout_id(d.qualifiers, p)) packing = p;
  const bool scalar = packing == "scalar";
  const bool explicit_layout = packing == "std140" || packing == "std430";
  auto forbid = [&](const ast::TypeQualifiers& q) {
    for (const char* id : {"offset", "align"})
      if (const ast::LayoutId* l = find_layout_id(q, id)) {
        reject(l->name_range, "layout '" + std::string(id) + "' requires a std140 or std430 block, not a " + packing + " one",
               code::E_LAYOUT);
        return false;
      }
    return true;
  };
  if (!explicit_layout && !scalar) {
    if (!forbid(d.qualifiers)) return;
    for (const ast::VariableDecl* m : d.members)
      if (!forbid(m->qualifiers)) return;
    return;
  }
  const PackingRules rules = scalar ? PackingRules::scalar : packing == "std140" ? PackingRules::std140 : PackingRules::std430;
  BlockLayout layout;
  layout.packing = packing;
  long long block_align = 1;
  if (const ast::LayoutId* a = find_layout_id(d.qualifiers, "align"))
    if (std::optional<long long> v = layout_value(*a)) block_align = *v;
  const bool block_row_major = find_layout_id(d.qualifiers, "row_major") != nullptr;
  long long next = 0;  // the first byte after the previous member
  // Each member's bytes, [begin, end): under Vulkan members may come in any order, so these are
  // what an offset must not overlap, and the block ends at the last of them.
  std::vector<std::pair<const ast::Declarator*, std::pair<long long, long long>>> placed_ranges;
  for (const ast::VariableDecl* m : d.members) {
    const ast::LayoutId* offset = find_layout_id(m->qualifiers, "offset");
    const ast::LayoutId* align = find_layout_id(m->qualifiers, "align");
    const bool row_major = find_layout_id(m->qualifiers, "row_major") ? true
                           : find_layout_id(m->qualifiers, "column_major") ? false
                                                                             : block_row_major;
    for (const ast::Declarator& decl : m->declarators) {
      const Type* t = result_.type_of(&decl);
      if (!t || t->shape == Shape::opaque) return;
      const bool runtime_sized = t->is_array() && t->array[0] < 0;
      const Packing p = packing_of(*t, rules, row_major);
      if (!p.known) {  // nothing from here on can be placed: the table gives the members before it
        result_.block_layouts[&d] = std::move(layout);
        return;
      }
      // A member's align overrides the block's (GLSL 4.60 §4.4.5); either only raises the base alignment.
      long long member_align = std::max(p.align, block_align);
      if (align)
        if (std::optional<long long> v = layout_value(*align)) member_align = std::max(p.align, *v);
      long long at = (next + member_align - 1) / member_align * member_align;
      // GL_EXT_scalar_block_layout: explicit offsets are the program's to choose; they are not checked against it.
      if (offset && &decl == &m->declarators.front()) {
        const std::optional<long long> v = layout_value(*offset);
        if (!v) return;
        if (!scalar && *v % p.align != 0) {
          reject(offset->value->range, "layout 'offset' " + std::to_string(*v) + " of '" + decl.name +
                                           "' is not a multiple of its base alignment (" + std::to_string(p.align) + " bytes)",
                 code::E_LAYOUT);
          return;
        }
        // Vulkan's rule is that members do not overlap, in any order (glslang targeting SPIR-V places a
        // member at its offset unchecked: `spv.offsets.frag` declares c, b, a); OpenGL's that each
        // member starts past the one before it.
        if (!scalar && vulkan_glsl(language())) {
          const long long end_of_member = *v + (runtime_sized ? 1 : p.size);
          for (const auto& [placed, range] : placed_ranges)
            if (*v < range.second && range.first < end_of_member) {
              reject(offset->value->range, "layout 'offset' " + std::to_string(*v) + " of '" + decl.name + "' overlaps '" +
                                               placed->name + "', bytes " + std::to_string(range.first) + " to " +
                                               std::to_string(range.second - 1),
                     code::E_LAYOUT);
              return;
            }
        } else if (!scalar && *v < next) {
          reject(offset->value->range, "layout 'offset' " + std::to_string(*v) + " of '" + decl.name +
                                           "' lies inside the member before it, which ends at byte " + std::to_string(next),
                 code::E_LAYOUT);
          return;
        }
        at = scalar ? *v : (*v + member_align - 1) / member_align * member_align;
      }
      layout.members[&decl] = {at, runtime_sized ? -1 : p.size, t->is_array() ? p.array_stride : 0, p.matrix_stride,
                               row_major && (t->shape == Shape::matrix), field_layouts(*t, rules, row_major)};
      if (runtime_sized) {  // the last member: the block's size depends on the buffer bound
        result_.block_layouts[&d] = std::move(layout);
        return;
      }
      next = at + p.size;
      placed_ranges.emplace_back(&decl, std::pair{at, next});
    }
  }
  layout.size = 0;
  for (const auto& placed : placed_ranges) layout.size = std::max(layout.size, placed.second.second);
  result_.block_layouts[&d] = std::move(layout);
}

}  // namespace safegi::detail
