// Scopes, declarations, functions and statements.

#include <safegi/parser/printer.hpp>
#include <cstring>

#include "checker_impl.hpp"
#include "dim_slot.hpp"
#include "validation.hpp"

namespace safegi::detail {
namespace {

struct BuiltinVariableEntry {
  const char* stages;
  const char* name;
  const char* type;
  bool writable;
  const char* extensions;  // "": none needed; else any one of these (space-separated)
};

constexpr BuiltinVariableEntry kBuiltinVariables[] = {
#define BUILTIN_VARIABLE(stages, name, type, writable) {stages, #name, type, writable, ""},
#define BUILTIN_VARIABLE_WITH(stages, name, type, writable, extensions) {stages, #name, type, writable, extensions},
#include "builtin_variables.def"
#undef BUILTIN_VARIABLE_WITH
#undef BUILTIN_VARIABLE
};

// Whether what a declaration holds leaves the stage: an `out`, or a `varying` of a vertex shader.
bool is_stage_output(const ast::TypeQualifiers& q, Stage stage) {
  return q.has("out") || (q.has("varying") && stage == Stage::vertex);
}

// Whether one of `extensions` (space-separated) is enabled; true when the language is unknown.
bool any_enabled(std::string_view extensions, const LanguageLevel* level) {
  if (!level) return true;
  while (!extensions.empty()) {
    const std::size_t space = extensions.find(' ');
    if (level->extension_enabled(extensions.substr(0, space))) return true;
    extensions = space == std::string_view::npos ? std::string_view() : extensions.substr(space + 1);
  }
  return false;
}

Type parse_simple_type(std::string_view text) {
  bool array = false;
  int size = -1;
  if (auto b = text.find('['); b != std::string_view::npos) {
    array = true;
    if (text[b + 1] != ']') size = text[b + 1] - '0';
    text = text.substr(0, b);
  }
  Type t;
  if (text == "int") t = Type::scalar_of(Scalar::int_);
  else if (text == "uint") t = Type::scalar_of(Scalar::uint_);
  else if (text == "bool") t = Type::scalar_of(Scalar::bool_);
  else if (text == "float") t = Type::scalar_of(Scalar::float_);
  else if (text == "vec2") t = Type::vector_of(Scalar::float_, 2);
  else if (text == "vec3") t = Type::vector_of(Scalar::float_, 3);
  else if (text == "vec4") t = Type::vector_of(Scalar::float_, 4);
  else if (text == "uvec2") t = Type::vector_of(Scalar::uint_, 2);
  else if (text == "uvec3") t = Type::vector_of(Scalar::uint_, 3);
  else if (text == "mat3") t = Type::matrix_of(Scalar::float_, 3, 3);
  else if (text == "mat4x3") t = Type::matrix_of(Scalar::float_, 4, 3);
  else if (text == "mat3x4") t = Type::matrix_of(Scalar::float_, 3, 4);
  else if (text == "void") t = Type::void_type();
  else if (text == "mat4") t = Type::matrix_of(Scalar::float_, 4, 4);
  if (array) t.array.push_back(size);
  return t;
}

}  // namespace

// A type of builtin_variables.def: a GLSL type, or `point<S>` / `direction<S>`
// (a vec3 in space S) or `float<D>`, annotated where the program declares S or
// D (`space world;`) and plain otherwise (gradual typing).
Type Checker::builtin_variable_type(std::string_view text) const {
  const std::size_t open = text.find('<');
  if (open == std::string_view::npos) return parse_simple_type(text);
  const std::string_view head = text.substr(0, open);
  const std::string_view argument = text.substr(open + 1, text.size() - open - 2);
  const DimensionRegistry& reg = result_.registry;
  if (head == "float") {
    Type t = Type::scalar_of(Scalar::float_);
    if (std::optional<Dimension> d = reg.find_dimension(argument)) t.dim = DimSlot::known(*d);
    return t;
  }
  Type t = Type::vector_of(Scalar::float_, 3);
  const std::optional<SpaceId> space = reg.find_space(argument);
  if (!space) return t;
  t.geometry = head == "point" ? Geometry::point : Geometry::direction;
  t.from = SpaceSlot::known(*space);
  if (t.geometry == Geometry::direction) t.dim = DimSlot::known(Dimension{});
  else if (std::optional<Dimension> length = reg.find_dimension("length")) t.dim = DimSlot::known(*length);
  return t;
}

namespace {

std::optional<int> layout_int(const ast::TypeQualifiers& q, const char* id, Checker& c) {
  for (const ast::Qualifier& qual : q.list)
    for (const ast::LayoutId& l : qual.layout_ids)
      if (l.name == id && l.value) {
        if (std::optional<long long> v = c.layout_value(l)) return static_cast<int>(*v);
      }
  return std::nullopt;
}

bool is_storage(const ast::TypeQualifiers& q, const char* word) { return q.has(word); }

}  // namespace

bool known_builtin_variable(std::string_view name) {
  for (const BuiltinVariableEntry& e : kBuiltinVariables)
    if (e.name == name) return true;
  return name == "gl_in" || name == "gl_out" || name == "gl_PerVertex";
}

Checker::Checker(const CheckOptions& options, DiagnosticEngine& diagnostics, CheckResult& result)
    : options_(options), diagnostics_(diagnostics), result_(result),
      symbols_(options.record_symbols ? &result.symbols : nullptr, result.registry) {
  if (options.tokens && options.sources) expansions_ = ExpansionFinder(*options.tokens, *options.sources);
}

void Checker::run(const ast::TranslationUnit& unit) {
  // Annotation declarations first: the built-in signatures are resolved against them.
  for (const ast::Decl* d : unit.decls) {
    if (const auto* dim = ast::dyn_cast<ast::DimensionDecl>(d)) declare_dimension(*dim);
    else if (const auto* u = ast::dyn_cast<ast::UnitDecl>(d)) declare_unit(*u);
    else if (const auto* s = ast::dyn_cast<ast::SpaceDecl>(d)) declare_space(*s);
  }
  symbols_.annotation_declarations(unit);
  builtins_ = BuiltinLibrary::for_registry(result_.registry);
  validate_stage(unit);
  push_scope();
  declare_builtin_variables();
  push_scope();  // the program's globals may shadow built-ins (redeclaring gl_* blocks)
  for (const ast::Decl* d : unit.decls) {
    if (diagnostics_.limit_reached()) break;
    global_decl(d);
  }
}

void Checker::declare_builtin_variables() {
  const char letter = stage_letter(options_.stage);
  for (const BuiltinVariableEntry& e : kBuiltinVariables) {
    if (letter != '*' && !std::strchr(e.stages, letter)) continue;
    if (*e.extensions && letter != '*' && !any_enabled(e.extensions, language())) continue;
    if (lookup(e.name)) continue;  // listed for several stages
    Variable v;
    v.name = e.name;
    const std::string_view type = e.type;
    const bool constant = type.rfind("const ", 0) == 0;
    v.type = builtin_variable_type(constant ? type.substr(6) : type);
    v.constant_expression = constant;
    v.read_only = !e.writable;
    v.builtin = true;
    scopes_.back().emplace(v.name, v);
  }
  // gl_in[] / gl_out[]: arrays of gl_PerVertex.
  auto per_vertex = std::make_unique<StructInfo>();
  per_vertex->name = "gl_PerVertex";
  per_vertex->fields = {{"gl_Position", Type::vector_of(Scalar::float_, 4)},
                        {"gl_PointSize", Type::scalar_of(Scalar::float_)},
                        {"gl_ClipDistance", parse_simple_type("float[]")},
                        {"gl_CullDistance", parse_simple_type("float[]")}};
  // GL_NV_stereo_view_rendering and GL_NVX_multiview_per_view_attributes add members (glslang's
  // spv.stereoViewRendering.tesc, spv.multiviewPerViewAttributes.tesc).
  if (const LanguageLevel* level = language(); level && level->extension_enabled("GL_NV_stereo_view_rendering")) {
    per_vertex->fields.push_back({"gl_SecondaryPositionNV", Type::vector_of(Scalar::float_, 4)});
    per_vertex->fields.push_back({"gl_SecondaryViewportMaskNV", parse_simple_type("int[]")});
  }
  if (const LanguageLevel* level = language(); level && level->extension_enabled("GL_NVX_multiview_per_view_attributes")) {
    per_vertex->fields.push_back({"gl_PositionPerViewNV", parse_simple_type("vec4[]")});
    per_vertex->fields.push_back({"gl_ViewportMaskPerViewNV", parse_simple_type("int[]")});
  }
  if (compatibility_profile()) {  // GLSL 1.50 compatibility §7.1: the fixed-function varyings
    for (const char* name : {"gl_FrontColor", "gl_BackColor", "gl_FrontSecondaryColor", "gl_BackSecondaryColor", "gl_ClipVertex"})
      per_vertex->fields.push_back({name, Type::vector_of(Scalar::float_, 4)});
    per_vertex->fields.push_back({"gl_TexCoord", parse_simple_type("vec4[]")});
    per_vertex->fields.push_back({"gl_FogFragCoord", Type::scalar_of(Scalar::float_)});
  }
  Type array;
  array.shape = Shape::structure;
  array.structure = per_vertex.get();
  array.array = {-1};
  structs_["gl_PerVertex"] = per_vertex.get();
  result_.structs.push_back(std::move(per_vertex));
  if (letter == '*' || letter == 'c' || letter == 'e' || letter == 'g') {
    scopes_.back().emplace("gl_in", Variable{"gl_in", array, {}, true, true, std::nullopt, {}});
  }
  if (letter == '*' || letter == 'c') {
    scopes_.back().emplace("gl_out", Variable{"gl_out", array, {}, false, true, std::nullopt, {}});
  }
}

std::string Checker::builtin_variable_extensions(const std::string& name) const {
  const char letter = stage_letter(options_.stage);
  for (const BuiltinVariableEntry& e : kBuiltinVariables)
    if (*e.extensions && e.name == name && std::strchr(e.stages, letter)) return e.extensions;
  return {};
}

std::string Checker::stages_owning_builtin(const std::string& name) const {
  const char letter = stage_letter(options_.stage);
  if (letter == '*') return {};
  std::string owners;  // stage letters, in the table's order
  auto owned_by = [&](const char* stages) {
    if (std::strchr(stages, letter)) return false;
    for (const char* s = stages; *s; ++s)
      if (owners.find(*s) == std::string::npos) owners += *s;
    return true;
  };
  for (const BuiltinVariableEntry& e : kBuiltinVariables)
    if (e.name == name && !*e.extensions && !owned_by(e.stages)) return {};
  // The gl_PerVertex arrays (declare_builtin_variables) are not in the table.
  if ((name == "gl_in" && !owned_by("ceg")) || (name == "gl_out" && !owned_by("c"))) return {};
  return stage_list(owners);
}

const Variable* Checker::lookup(const std::string& name) const {
  for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
    auto found = it->find(name);
    if (found != it->end()) return &found->second;
  }
  return nullptr;
}

void Checker::declare_variable(Variable v) {
  auto& scope = scopes_.back();
  auto it = scope.find(v.name);
  // Built-ins may be redeclared (`layout(origin_upper_left) in vec4 gl_FragCoord;`), even twice; so may an
  // unsized array, with a size (GLSL 1.20 §4.1.9).
  const auto sizes_unsized_array = [&](const Type& before) {
    return before.is_array() && before.array[0] < 0 && v.type.is_array() && same_glsl_type(before.element(), v.type.element());
  };
  if (it != scope.end() && !it->second.builtin && v.name.rfind("gl_", 0) != 0 && !sizes_unsized_array(it->second.type)) {
    Diagnostic d = Diagnostic::error(v.range, "redefinition of '" + v.name + "'").with_code(code::E_REDEFINITION);
    d.with_note(Diagnostic::note(it->second.range, "previous definition is here"));
    report(std::move(d));
    return;
  }
  scope.insert_or_assign(v.name, std::move(v));
}

void Checker::record_interface(const ast::TypeQualifiers& q, const std::string& name, const std::string& block,
                               const Type& t, SourceRange range, const ast::Node* decl) {
  std::optional<InterfaceKind> kind;
  if (is_storage(q, "uniform")) kind = InterfaceKind::uniform;
  else if (is_storage(q, "buffer")) kind = InterfaceKind::buffer;
  else if (is_storage(q, "shared")) kind = InterfaceKind::shared;
  else if (is_storage(q, "in") || is_storage(q, "attribute")) kind = InterfaceKind::input;
  else if (is_storage(q, "out")) kind = InterfaceKind::output;
  else if (is_storage(q, "varying")) kind = options_.stage == Stage::vertex ? InterfaceKind::output : InterfaceKind::input;
  else if (is_storage(q, "rayPayloadEXT") || is_storage(q, "rayPayloadNV")) kind = InterfaceKind::ray_payload;
  else if (is_storage(q, "rayPayloadInEXT") || is_storage(q, "rayPayloadInNV")) kind = InterfaceKind::ray_payload_in;
  if (!kind) return;
  InterfaceVariable iv;
  iv.kind = *kind;
  iv.name = name;
  iv.block = block;
  iv.type = t;
  iv.type_text = name_of(t);
  iv.range = range;
  iv.decl = decl;
  iv.location = layout_int(q, "location", *this).value_or(-1);
  iv.binding = layout_int(q, "binding", *this).value_or(-1);
  iv.set = layout_int(q, "set", *this).value_or(-1);
  iv.push_constant = q.has_layout_id("push_constant");
  iv.shader_record = q.has_layout_id("shaderRecordEXT") || q.has_layout_id("shaderRecordNV");
  iv.annotated = t.is_annotated();
  if (options_.strict && !iv.annotated && (t.shape == Shape::scalar || t.shape == Shape::vector || t.shape == Shape::matrix) &&
      t.scalar != Scalar::bool_ && t.is_floating()) {
    report(Diagnostic::warning(range, "interface variable '" + name + "' has no annotation")
               .with_code(code::W_UNANNOTATED_INTERFACE)
               .with_hint("give it a dimension or a space, e.g. '" + glsl_name(t.element()) + "<1>' if it is a pure number"));
  }
  result_.interface.push_back(std::move(iv));
}

void Checker::record_specialization_constant(const ast::TypeQualifiers& q, const ast::Declarator& decl, const Type& t,
                                             const Variable& v) {
  const std::optional<int> id = layout_int(q, "constant_id", *this);
  if (!id) return;
  SpecializationConstant c{decl.name, *id, t, name_of(t), decl.name_range, v.constant, v.number};
  result_.specialization_constants.push_back(std::move(c));
}

// `layout(local_size_x_id = N) in;`: the work group's size in x, set by the host.
void Checker::record_work_group_size_ids(const ast::TypeQualifiers& q, SourceRange range) {
  static constexpr std::pair<const char*, const char*> kAxes[] = {
      {"local_size_x_id", "gl_WorkGroupSize.x"}, {"local_size_y_id", "gl_WorkGroupSize.y"}, {"local_size_z_id", "gl_WorkGroupSize.z"}};
  for (const auto& [layout, name] : kAxes)
    if (const std::optional<int> id = layout_int(q, layout, *this)) {
      const Type uint_type = Type::scalar_of(Scalar::uint_);
      result_.specialization_constants.push_back({name, *id, uint_type, name_of(uint_type), range, std::nullopt, std::nullopt});
    }
}

void Checker::global_decl(const ast::Decl* d) {
  switch (d->kind) {
    case ast::NodeKind::VariableDecl: variable_decl(*static_cast<const ast::VariableDecl*>(d), true); break;
    case ast::NodeKind::InterfaceBlockDecl: block_decl(*static_cast<const ast::InterfaceBlockDecl*>(d)); break;
    case ast::NodeKind::FunctionDecl: function_decl(*static_cast<const ast::FunctionDecl*>(d)); break;
    case ast::NodeKind::QualifierDecl: {
      const auto& qualifier_decl = *static_cast<const ast::QualifierDecl*>(d);
      validate_qualifier_decl(qualifier_decl, true);
      if (qualifier_decl.qualifiers.has("in")) record_work_group_size_ids(qualifier_decl.qualifiers, d->range);
      break;
    }
    case ast::NodeKind::PrecisionDecl: validate_precision(*static_cast<const ast::PrecisionDecl*>(d)); break;
    case ast::NodeKind::StructDecl: {
      validate_struct_members(*static_cast<const ast::StructDecl*>(d));
      ast::TypeSpecifier spec;
      spec.form = ast::TypeSpecifier::Form::Struct;
      spec.struct_decl = const_cast<ast::StructDecl*>(static_cast<const ast::StructDecl*>(d));
      resolve_type(&spec);
      break;
    }
    default: break;  // precision, qualifier-only, annotation declarations (done), empty
  }
}

void Checker::variable_decl(const ast::VariableDecl& d, bool global) {
  const bool is_const = d.qualifiers.has("const");
  const bool is_input = d.qualifiers.has("uniform") || d.qualifiers.has("in") || d.qualifiers.has("attribute") ||
                        (d.qualifiers.has("varying") && options_.stage != Stage::vertex && !d.qualifiers.has("out"));
  const Type base = resolve_type(d.type);  // once: an inline struct is declared once
  validate_variable(d, base, global);
  if (global) validate_interface(d, base);
  for (const ast::Declarator& decl : d.declarators) {
    Type declared = base.is_error() ? base : with_array_dims(base, decl.array_dims);
    if (global) mark_stage_normal(declared, d.qualifiers);
    Variable v;
    bool poisoned = false;
    v.name = decl.name;
    v.range = decl.name_range;
    v.read_only = is_const || (global && is_input);
    v.stage_output = global && is_stage_output(d.qualifiers, options_.stage);
    v.origin = {decl.name_range, "'" + decl.name + "' declared here"};
    if (declared.shape == Shape::void_) {
      report(Diagnostic::error(decl.name_range, "variable '" + decl.name + "' declared void").with_code(code::E_VOID_VARIABLE));
      declared = Type::error();
    }
    bool pi_multiple = false;
    if (const auto* list = ast::dyn_cast<ast::InitializerList>(decl.initializer)) {
      if (list->elements.empty() && !declared.array.empty() && declared.array[0] < 0) {  // glslang's rule
        report(Diagnostic::error(list->range, "an empty initializer '{}' cannot size the unsized array '" + decl.name + "'")
                   .with_code(code::E_INIT_LIST));
      }
      initializer_list(*list, declared);
    } else if (decl.initializer) {
      Value init = expr(decl.initializer);
      pi_multiple = init.pi_multiple;
      if (!declared.is_annotated()) v.inverse_squares = init.inverse_squares;
      v.perpendicular_to = init.perpendicular_to;
      v.unit_sign = init.unit_sign && !declared.is_annotated();
      v.plane_normal = init.plane_normal && !declared.is_annotated();
      if (declared.shape == Shape::scalar && declared.is_floating() && !declared.is_array()) {
        v.length_of = init.length_of;
        if (const auto* dot = ast::dyn_cast<ast::CallExpr>(ast::without_parens(decl.initializer));
            dot && dot->callee == "dot" && dot->args.size() == 2)
          v.dot_of = std::pair{print_expression(*dot->args[0]), print_expression(*dot->args[1])};
      }
      if (is_const && init.literal && init.number && !declared.is_annotated() && declared.shape == Shape::scalar &&
          declared.is_floating() && !declared.is_array())
        v.pi_constant = pi_constant(decl.name, *init.number);
      // `vec3 diffuse = albedo / PI;`: an unannotated local holding a product with a π constant carries it on.
      if (!v.pi_constant && init.pi_factor && !declared.is_annotated() &&
          value_dimension(declared, result_.registry).state == DimSlot::State::unknown)
        v.pi_constant = init.pi_factor;
      // Unsized arrays take their size from the initialiser.
      if (!declared.array.empty() && declared.array[0] < 0 && !init.type.array.empty()) declared.array[0] = init.type.array[0];
      const bool infer = !global && !declared.is_annotated() && !declared.is_error() && !init.type.is_error() &&
                         !init.zero && declared.shape != Shape::structure && declared.shape != Shape::opaque &&
                         declared.rows == init.type.rows && declared.shape == init.type.shape && declared.array == init.type.array;
      if (infer && init.type.is_annotated()) {
        // `auto`-style inference of unannotated locals (docs/language.md, gradual typing),
        // once the GLSL types agree.
        if (check_assignable(declared, init, decl.name_range, decl.name, v.origin, "initialize")) {
          Type inferred = init.type;
          inferred.scalar = declared.scalar;
          declared = inferred;
          v.origin = {decl.initializer->range, "type of '" + decl.name + "' inferred from its initializer", true};
        } else {
          poisoned = true;
        }
      } else if (infer_from_zero(global, declared, init)) {
        v.zero_start = true;  // an accumulator: `vec3 sum = vec3(0.0); sum += …`
      } else if (!declared.is_error() && !check_assignable(declared, init, decl.name_range, decl.name, v.origin, "initialize")) {
        poisoned = true;  // one mistake, one error: later uses of this variable stay silent
      }
      if (is_const && init.constant && declared.shape == Shape::scalar && declared.is_integer()) v.constant = init.constant;
      if (is_const && init.number && declared.shape == Shape::scalar && declared.is_floating()) v.number = init.number;
    } else if (is_const && !global) {
      report(Diagnostic::error(decl.name_range, "const variable '" + decl.name + "' needs an initializer").with_code(code::E_CONST_INIT));
    }
    v.pi_multiple = pi_multiple && !base.is_annotated();  // a declared float<1> has said what it is
    if (is_const && decl.initializer) validate_const_initializer(decl, global);
    else if (global && decl.initializer) validate_global_initializer(decl);
    v.constant_expression = is_const && decl.initializer && !non_constant_part(decl.initializer);
    v.type = poisoned ? Type::error() : declared;
    result_.declarators[&decl] = declared;
    if (global && decl.name.rfind("gl_", 0) == 0) validate_builtin_redeclaration(d, decl, declared);
    symbols_.declare_variable(decl.name, decl.name_range, declared);
    if (global) record_interface(d.qualifiers, decl.name, "", declared, decl.name_range, &d);
    if (global && is_const) record_specialization_constant(d.qualifiers, decl, declared, v);
    declare_variable(std::move(v));
  }
  if (global) validate_global_layouts(d);
}

StructInfo* Checker::buffer_reference_type(const std::string& name) {
  if (auto it = structs_.find(name); it != structs_.end() && it->second->buffer_reference)
    return const_cast<StructInfo*>(it->second);  // declared before (result_.structs owns it)
  auto info = std::make_unique<StructInfo>();
  info->name = name;
  info->buffer_reference = true;
  StructInfo* raw = info.get();
  structs_[name] = raw;
  result_.structs.push_back(std::move(info));
  return raw;
}

// `layout(buffer_reference) buffer Node { Node next; float<length> t; };`: a
// type, not a resource; its members are reached through a reference.
void Checker::buffer_reference_block(const ast::InterfaceBlockDecl& d) {
  StructInfo* info = buffer_reference_type(d.block_name);
  info->fields.clear();
  info->read_only = d.qualifiers.has("readonly");
  for (const ast::VariableDecl* member : d.members)
    for (const ast::Declarator& decl : member->declarators) {
      Type t = resolve_type(member->type, &decl.array_dims);
      result_.declarators[&decl] = t;
      info->fields.push_back({decl.name, t, member->qualifiers.has("readonly")});
    }
  symbols_.declare_fields(info, d.members);
  validate_block_layouts(d);
  reference_strides_.erase(info);
  if (auto layout = result_.block_layouts.find(&d); layout != result_.block_layouts.end() && layout->second.size >= 0) {
    long long align = 16;
    if (const ast::LayoutId* a = find_layout_id(d.qualifiers, "buffer_reference_align"))
      if (std::optional<long long> v = layout_value(*a); v && *v > 0) align = *v;
    reference_strides_[info] = (layout->second.size + align - 1) / align * align;
  }
}

void Checker::block_decl(const ast::InterfaceBlockDecl& d) {
  const bool reference_type = d.qualifiers.has_layout_id("buffer_reference");
  if (reference_type) {
    buffer_reference_block(d);
    // `layout(buffer_reference, set = 3, binding = 1) buffer T { … } x;` (glslang): T is the type of a
    // reference, and x a storage buffer of T's members at that set and binding (spv.bufferhandle6.frag).
    if (d.instance_name.empty()) return;
  }
  auto info = std::make_unique<StructInfo>();
  info->name = d.block_name;
  const bool read_only = d.qualifiers.has("uniform") || d.qualifiers.has("in") || d.qualifiers.has("readonly");
  for (const ast::VariableDecl* member : d.members) {
    for (const ast::Declarator& decl : member->declarators) {
      Type t = resolve_type(member->type, &decl.array_dims);
      mark_stage_normal(t, d.qualifiers, member->qualifiers.has("flat"));
      result_.declarators[&decl] = t;
      info->fields.push_back({decl.name, t});
      const std::string full = d.instance_name.empty() ? decl.name : d.instance_name + "." + decl.name;
      record_interface(d.qualifiers, full, d.block_name, t, decl.name_range, member);
      if (d.instance_name.empty()) {
        symbols_.declare_variable(decl.name, decl.name_range, t);
        Variable v{decl.name, t, decl.name_range, read_only || member->qualifiers.has("readonly"), false, std::nullopt,
                   {decl.name_range, "'" + decl.name + "' declared here"}};
        v.stage_output = is_stage_output(d.qualifiers, options_.stage);
        declare_variable(std::move(v));
      }
    }
  }
  if (!d.instance_name.empty()) {
    symbols_.declare_fields(info.get(), d.members);
    Type t;
    t.shape = Shape::structure;
    t.structure = info.get();
    for (const ast::ArrayDim& dim : d.instance_array_dims) t.array.push_back(static_cast<int>(array_size(dim).value_or(-1)));
    Variable v{d.instance_name, t, d.instance_name_range, read_only, false, std::nullopt,
               {d.instance_name_range, "'" + d.instance_name + "' declared here"}};
    v.stage_output = is_stage_output(d.qualifiers, options_.stage);
    symbols_.declare_variable(d.instance_name, d.instance_name_range, t);
    declare_variable(std::move(v));
  }
  result_.structs.push_back(std::move(info));
  validate_block(d, !reference_type);  // a reference block's layout was placed by buffer_reference_block
}

void Checker::function_decl(const ast::FunctionDecl& d) {
  Function f;
  f.name = d.name;
  f.decl = &d;
  for (const ast::TemplateParam& p : d.template_params)
    (p.kind == ast::TemplateParamKind::Dimension ? f.dim_params : f.space_params).push_back(p.name);
  template_dims_ = &f.dim_params;
  template_spaces_ = &f.space_params;
  symbols_.enter_function(&d);
  f.result = resolve_type(d.return_type);
  for (const ast::ParamDecl* p : d.params) {
    Type t = resolve_type(p->type, &p->array_dims);
    result_.types[p] = t;
    f.params.push_back(t);
    f.out_params.push_back(p->qualifiers.has("out") || p->qualifiers.has("inout"));
    f.inout_params.push_back(p->qualifiers.has("inout"));
    f.by_reference_params.push_back(p->qualifiers.has("spirv_by_reference"));
    f.literal_params.push_back(p->qualifiers.has("spirv_literal"));
  }
  f.defined = d.body != nullptr;
  symbols_.declare_function(d, f.result, f.params);
  validate_function(d, f);
  if (subroutine_declaration(d, f)) {
    template_dims_ = nullptr;
    template_spaces_ = nullptr;
    return;  // a subroutine type, not a function
  }

  // Overloads are told apart by GLSL parameter types; a second definition is an error.
  std::vector<Function>& overloads = functions_[d.name];
  Function* existing = nullptr;
  for (Function& o : overloads) {
    if (o.params.size() != f.params.size()) continue;
    bool same = true;
    for (std::size_t i = 0; i < f.params.size(); ++i) same = same && same_glsl_type(o.params[i], f.params[i]);
    if (same) existing = &o;
  }
  if (existing) {
    if (existing->defined && f.defined) {
      report(Diagnostic::error(d.name_range, "redefinition of '" + d.name + "'")
                 .with_code(code::E_REDEFINITION)
                 .with_note(Diagnostic::note(existing->decl->name_range, "previous definition is here")));
    } else if (!same_glsl_type(existing->result, f.result)) {
      report(Diagnostic::error(d.name_range, "'" + d.name + "' is redeclared with a different return type")
                 .with_code(code::E_REDEFINITION)
                 .with_note(Diagnostic::note(existing->decl->name_range, "previous declaration is here")));
    }
    if (f.defined) *existing = f;
  } else {
    overloads.push_back(f);
  }

  if (d.body) {
    const Function* self = nullptr;
    for (const Function& o : functions_[d.name])
      if (o.decl == &d) self = &o;
    current_function_ = self;
    push_scope();
    for (std::size_t i = 0; i < d.params.size(); ++i) {
      const ast::ParamDecl* p = d.params[i];
      if (p->name.empty()) continue;
      const bool in_only = !p->qualifiers.has("out") && !p->qualifiers.has("inout");
      symbols_.declare_variable(p->name, p->name_range, f.params[i]);
      declare_variable({p->name, f.params[i], p->name_range, p->qualifiers.has("const") && in_only, false, std::nullopt,
                        {p->name_range, "'" + p->name + "' declared here"}});
    }
    for (const ast::Stmt* s : d.body->statements) statement(s);
    pop_scope();
    current_function_ = nullptr;
  }
  template_dims_ = nullptr;
  template_spaces_ = nullptr;
  symbols_.enter_function(nullptr);
}

void Checker::statement(const ast::Stmt* s) {
  if (!s || diagnostics_.limit_reached()) return;
  // The innermost statement the user wrote (not one a macro produced) tells
  // apart the expansions of a macro used several times (report()).
  const bool written = !expansions_.from_macro(s->range);
  if (written) written_statements_.push_back(s->range);
  struct Pop {
    std::vector<SourceRange>* stack;
    ~Pop() {
      if (stack) stack->pop_back();
    }
  } pop{written ? &written_statements_ : nullptr};
  const FlowScope flow(*this, s);
  // [[dependency_length(4)]]: the argument is checked as an expression; what the attribute
  // asks of it is the driver's (glslang only warns).
  for (const ast::StatementAttribute& a : s->attributes)
    if (a.argument) expr(a.argument);
  switch (s->kind) {
    case ast::NodeKind::CompoundStmt:
      push_scope();
      for (const ast::Stmt* c : static_cast<const ast::CompoundStmt*>(s)->statements) statement(c);
      pop_scope();
      break;
    case ast::NodeKind::DeclStmt: {
      const ast::Decl* d = static_cast<const ast::DeclStmt*>(s)->decl;
      if (const auto* v = ast::dyn_cast<ast::VariableDecl>(d)) variable_decl(*v, false);
      else if (const auto* f = ast::dyn_cast<ast::FunctionDecl>(d)) function_decl(*f);
      else if (const auto* st = ast::dyn_cast<ast::StructDecl>(d)) global_decl(st);
      else if (const auto* qd = ast::dyn_cast<ast::QualifierDecl>(d)) validate_qualifier_decl(*qd, false);
      else if (const auto* pd = ast::dyn_cast<ast::PrecisionDecl>(d)) validate_precision(*pd);
      note_writes(s);
      break;
    }
    case ast::NodeKind::ExprStmt:
      if (const ast::Expr* e = static_cast<const ast::ExprStmt*>(s)->expr) expr(e);
      note_writes(s);
      break;
    case ast::NodeKind::IfStmt: {
      const auto* i = static_cast<const ast::IfStmt*>(s);
      condition(i->condition);
      push_scope();
      statement(i->then_stmt);
      pop_scope();
      push_scope();
      statement(i->else_stmt);
      pop_scope();
      break;
    }
    case ast::NodeKind::SwitchStmt: {
      const auto* sw = static_cast<const ast::SwitchStmt*>(s);
      Value sel = expr(sw->selector);
      if (!sel.type.is_error() && !(sel.type.shape == Shape::scalar && sel.type.is_integer() && !sel.type.is_array()))
        report(Diagnostic::error(sel.range, "switch selector must be int or uint, found " + name_of(sel.type)).with_code(code::E_SWITCH_TYPE));
      validate_switch(*sw, sel.type);  // opens the switch its case labels are checked against
      ++loop_depth_;  // `break` is valid inside a switch
      statement(sw->body);
      --loop_depth_;
      switches_.pop_back();
      break;
    }
    case ast::NodeKind::CaseLabel:
      if (const ast::Expr* e = static_cast<const ast::CaseLabel*>(s)->value) validate_case(*static_cast<const ast::CaseLabel*>(s), expr(e));
      break;
    case ast::NodeKind::WhileStmt: {
      const auto* w = static_cast<const ast::WhileStmt*>(s);
      note_writes(s);  // what the body writes, the next iteration sees from the start
      push_scope();
      if (w->condition.decl) variable_decl(*w->condition.decl, false);
      else condition(w->condition.expr);
      ++loop_depth_;
      statement(w->body);
      --loop_depth_;
      pop_scope();
      break;
    }
    case ast::NodeKind::DoStmt: {
      const auto* w = static_cast<const ast::DoStmt*>(s);
      note_writes(s);  // what the body writes, the next iteration sees from the start
      ++loop_depth_;
      statement(w->body);
      --loop_depth_;
      condition(w->condition);
      break;
    }
    case ast::NodeKind::ForStmt: {
      const auto* f = static_cast<const ast::ForStmt*>(s);
      note_writes(s);  // what the body writes, the next iteration sees from the start
      push_scope();
      statement(f->init);
      if (f->condition.decl) variable_decl(*f->condition.decl, false);
      else if (f->condition.expr) condition(f->condition.expr);
      if (f->increment) expr(f->increment);
      ++loop_depth_;
      statement(f->body);
      --loop_depth_;
      pop_scope();
      break;
    }
    case ast::NodeKind::BreakStmt:
    case ast::NodeKind::ContinueStmt:
      if (loop_depth_ == 0)
        report(Diagnostic::error(s->range, std::string("'") + (s->kind == ast::NodeKind::BreakStmt ? "break" : "continue") +
                                               "' outside of a loop")
                   .with_code(code::E_JUMP_OUTSIDE_LOOP));
      break;
    case ast::NodeKind::DiscardStmt:
      if (options_.stage != Stage::unknown && options_.stage != Stage::fragment)
        report(Diagnostic::error(s->range, "'discard' is only allowed in fragment shaders").with_code(code::E_DISCARD_STAGE));
      break;
    case ast::NodeKind::ReturnStmt: {
      const auto* r = static_cast<const ast::ReturnStmt*>(s);
      if (!current_function_) break;
      const Type& want = current_function_->result;
      if (!r->value) {
        if (want.shape != Shape::void_ && !want.is_error())
          report(Diagnostic::error(s->range, "non-void function '" + current_function_->name + "' must return a value")
                     .with_code(code::E_RETURN));
        break;
      }
      Value v = expr(r->value);
      if (want.shape == Shape::void_) {
        if (!v.type.is_error())
          report(Diagnostic::error(r->value->range, "void function '" + current_function_->name + "' cannot return a value")
                     .with_code(code::E_RETURN));
        break;
      }
      std::optional<Origin> origin = Origin{current_function_->decl->return_type->range,
                                            "return type of '" + current_function_->name + "' declared here"};
      check_assignable(want, v, r->value->range, current_function_->name, origin, "return");
      break;
    }
    default: break;
  }
}

}  // namespace safegi::detail
