// The symbol table of a checked stage (docs/symbol-table.md), built as a
// safegi::gl::SymbolTable so that what the compiler writes is what the
// runtime reads.

#include <algorithm>
#include <set>
#include <sstream>
#include <unordered_map>

#include <safegi/lexer/extensions.hpp>

#include "safegi/elider/elider.hpp"

namespace safegi {
namespace {

constexpr std::string_view kBuiltinDir = "<builtin>";

gl::SourceLocation location_of(const SourceManager& sources, SourceLocation loc) {
  gl::SourceLocation out;
  if (!loc.valid()) return out;
  PresumedLocation p = sources.presumed(loc);
  out.file = std::string(p.file_name);
  if (out.file.rfind(kBuiltinDir, 0) == 0) out.file = std::string(kBuiltinDir);
  out.line = static_cast<int>(p.line);
  out.column = static_cast<int>(p.column);
  return out;
}

gl::DimensionExponents exponents_of(const Dimension& d, const DimensionRegistry& registry) {
  gl::DimensionExponents out;
  // A unit factor is written by its unit's name: a typed host value in reference
  // units then does not match a `float<length in centimeter>` (fail closed).
  for (const Factor& f : d.factors()) out[registry.factor_name(f.base)] = f.exponent;
  return out;
}

class SymbolBuilder {
 public:
  explicit SymbolBuilder(const ElideInput& input)
      : in_(input), registry_(input.checked.registry),
        vulkan_(input.preprocessed.language.extension_enabled(kVulkanGlslExtension)) {}

  gl::ValueType value_type(const Type& t) const {
    gl::ValueType v;
    v.glsl_type = glsl_name(t.element());
    // A spirv_type (GL_EXT_spirv_intrinsics) is opaque to a host: its arguments are in printed_type.
    if (v.glsl_type.rfind("spirv_type", 0) == 0) v.glsl_type = "spirv_type";
    auto space = [&](const SpaceSlot& s) { return s.is_known() ? registry_.space_name(s.id) : std::string("?"); };
    switch (t.geometry) {
      case Geometry::spectrum: v.kind = gl::Kind::spectrum; break;
      case Geometry::point: v.kind = gl::Kind::point; break;
      case Geometry::vector: v.kind = gl::Kind::vector; break;
      case Geometry::direction: v.kind = gl::Kind::direction; break;
      case Geometry::normal: v.kind = gl::Kind::normal; break;
      case Geometry::hpoint: v.kind = gl::Kind::hpoint; break;
      case Geometry::map:
      case Geometry::rigidmap: v.kind = gl::Kind::map; break;
      case Geometry::projmap: v.kind = gl::Kind::projective_map; break;
      case Geometry::none:
        if (t.texel) v.kind = gl::Kind::sampler;
        else if (t.dim.is_known()) v.kind = gl::Kind::scalar;
        else v.kind = gl::Kind::plain;
        break;
    }
    if (has_space(t.geometry)) v.spaces.push_back(space(t.from));
    if (is_map(t.geometry)) v.spaces.push_back(space(t.to));
    if ((v.kind == gl::Kind::scalar || v.kind == gl::Kind::spectrum) && t.dim.is_known()) {
      v.dimension.exponents = exponents_of(t.dim.value, registry_);
      v.dimension.name = t.dim.spelling.empty() ? registry_.format(t.dim.value, Notation::ascii) : t.dim.spelling;
    }
    return v;
  }

  gl::Symbol symbol(const InterfaceVariable& iv, gl::Storage storage, const std::string& name) const {
    gl::Symbol s;
    s.name = name;
    s.storage = storage;
    s.type = value_type(iv.type);
    s.printed_type = type_name(iv.type.element(), registry_);
    // A type the checker does not model (uint64_t, f16vec3, ...) is named as the program wrote it.
    if (iv.type.is_error())
      if (const auto* declaration = ast::dyn_cast<ast::VariableDecl>(iv.decl); declaration && declaration->type)
        s.type.glsl_type = s.printed_type = declaration->type->name;
    if (iv.type.texel) s.texel = value_type(*iv.type.texel);
    if (iv.type.is_array() && iv.type.array.front() > 0) s.array_size = iv.type.array.front();
    s.unsized = iv.type.is_array() && !s.array_size;
    if (iv.location >= 0) s.location = iv.location;
    if (iv.binding >= 0) s.binding = iv.binding;
    s.set = descriptor_set(iv, storage);
    s.declared_at = location_of(in_.sources, iv.range.begin);
    return s;
  }

  // A struct's fields (an array of structs': its element's) as symbols at the declaration that holds
  // the struct; lay_out places them.
  std::vector<gl::Symbol> fields(const Type& t, gl::Storage storage, const gl::SourceLocation& at) const {
    const Type element = t.is_array() ? t.element() : t;
    std::vector<gl::Symbol> out;
    if (element.shape != Shape::structure || !element.structure || element.structure->buffer_reference) return out;
    for (const StructField& f : element.structure->fields) {
      gl::Symbol field;
      field.name = f.name;
      field.storage = storage;
      field.type = value_type(f.type);
      field.printed_type = type_name(f.type.element(), registry_);
      if (f.type.is_array() && f.type.array.front() > 0) field.array_size = f.type.array.front();
      field.unsized = f.type.is_array() && !field.array_size;
      field.declared_at = at;
      field.fields = fields(f.type, storage, at);
      out.push_back(std::move(field));
    }
    return out;
  }

  static void place(gl::Symbol& symbol, const MemberLayout& at) {
    symbol.offset = at.offset;
    if (at.size >= 0) symbol.size = at.size;
    if (at.array_stride > 0) symbol.array_stride = at.array_stride;
    if (at.matrix_stride > 0) symbol.matrix_stride = at.matrix_stride;
    symbol.row_major = at.row_major;
    if (symbol.fields.size() == at.fields.size())
      for (std::size_t i = 0; i < at.fields.size(); ++i) place(symbol.fields[i], at.fields[i]);
  }

  // layout(set = N), or 0 for a Vulkan uniform or buffer resource that names
  // none (GL_KHR_vulkan_glsl); push constants and shader records are in no set.
  std::optional<int> descriptor_set(const InterfaceVariable& iv, gl::Storage storage) const {
    if (iv.set >= 0) return iv.set;
    // glslang gives a spirv_type uniform (GL_EXT_spirv_intrinsics) no DescriptorSet of its own.
    if (iv.type.shape == Shape::opaque && iv.type.opaque.rfind("spirv_type", 0) == 0) return std::nullopt;
    const bool resource = storage == gl::Storage::uniform || storage == gl::Storage::buffer;
    if (vulkan_ && resource && !iv.push_constant && !iv.shader_record) return 0;
    return std::nullopt;
  }

  // Where a block's members lie, when its packing says (std140, std430, scalar).
  void lay_out(gl::Symbol& block, const ast::InterfaceBlockDecl& decl) const {
    const auto found = in_.checked.block_layouts.find(&decl);
    if (found == in_.checked.block_layouts.end()) return;
    const BlockLayout& layout = found->second;
    block.packing = layout.packing;
    if (layout.size >= 0) block.size = layout.size;
    for (gl::Symbol& member : block.members)
      for (const ast::VariableDecl* m : decl.members)
        for (const ast::Declarator& d : m->declarators) {
          if (d.name != member.name) continue;
          const auto placed = layout.members.find(&d);
          if (placed == layout.members.end()) continue;
          place(member, placed->second);
        }
  }

  std::vector<gl::SpecializationConstant> specialization_constants() const {
    std::vector<gl::SpecializationConstant> out;
    for (const SpecializationConstant& c : in_.checked.specialization_constants) {
      gl::SpecializationConstant s;
      s.name = c.name;
      s.id = c.id;
      s.type = value_type(c.type);
      s.printed_type = c.type_text;
      if (c.integer_value) s.default_value = static_cast<double>(*c.integer_value);
      else if (c.float_value) s.default_value = *c.float_value;
      s.declared_at = location_of(in_.sources, c.range.begin);
      out.push_back(std::move(s));
    }
    return out;
  }

  std::vector<gl::Symbol> symbols() const {
    std::unordered_map<const ast::Node*, const ast::InterfaceBlockDecl*> block_of;
    for (const ast::Decl* d : in_.unit.decls)
      if (auto* b = ast::dyn_cast<ast::InterfaceBlockDecl>(d))
        for (const ast::VariableDecl* m : b->members) block_of[m] = b;

    std::vector<gl::Symbol> out;
    const ast::InterfaceBlockDecl* open_block = nullptr;
    auto close_block = [&] {
      if (open_block) lay_out(out.back(), *open_block);
      open_block = nullptr;
    };
    for (const InterfaceVariable& iv : in_.checked.interface) {
      std::optional<gl::Storage> storage;
      switch (iv.kind) {
        case InterfaceKind::uniform: storage = gl::Storage::uniform; break;
        case InterfaceKind::input: storage = gl::Storage::input; break;
        case InterfaceKind::output: storage = gl::Storage::output; break;
        case InterfaceKind::buffer: storage = gl::Storage::buffer; break;
        case InterfaceKind::shared: break;  // workgroup memory: no host ever sees it
        case InterfaceKind::ray_payload:
        case InterfaceKind::ray_payload_in: break;  // passed between ray-tracing stages, never bound by a host
      }
      if (!storage) continue;
      auto found = block_of.find(iv.decl);
      if (iv.block.empty() || found == block_of.end()) {
        close_block();
        out.push_back(symbol(iv, *storage, iv.name));
        continue;
      }
      const ast::InterfaceBlockDecl* block = found->second;
      if (block != open_block) {
        close_block();
        open_block = block;
        gl::Symbol b;
        b.name = block->block_name;
        b.storage = *storage;
        b.type.kind = gl::Kind::block;
        b.type.glsl_type = block->block_name;
        b.printed_type = block->block_name;
        b.instance_name = block->instance_name;
        if (!block->instance_array_dims.empty() && block->instance_array_dims.front().size)
          if (auto* lit = ast::dyn_cast<ast::LiteralExpr>(block->instance_array_dims.front().size))
            if (auto n = integer_literal_value(lit->spelling); n && *n > 0 && *n < (1u << 31)) b.array_size = static_cast<int>(*n);
        for (const ast::Qualifier& q : block->qualifiers.list)
          for (const ast::LayoutId& id : q.layout_ids)
            if (id.name == "binding" && id.value)
              if (auto* lit = ast::dyn_cast<ast::LiteralExpr>(id.value))
                if (auto n = integer_literal_value(lit->spelling); n && *n < (1u << 31)) b.binding = static_cast<int>(*n);
        b.declared_at = location_of(in_.sources, block->block_name_range.begin);
        b.push_constant = iv.push_constant;
        b.shader_record = iv.shader_record;
        b.set = descriptor_set(iv, *storage);
        out.push_back(std::move(b));
      }
      std::string member = iv.name;
      if (!block->instance_name.empty() && member.rfind(block->instance_name + ".", 0) == 0)
        member = member.substr(block->instance_name.size() + 1);
      gl::Symbol m = symbol(iv, *storage, member);
      m.block = block->block_name;
      m.fields = fields(iv.type, *storage, m.declared_at);
      out.back().members.push_back(std::move(m));
    }
    close_block();
    return out;
  }

 private:
  const ElideInput& in_;
  const DimensionRegistry& registry_;
  const bool vulkan_;
};

}  // namespace

gl::StageSymbols stage_symbols(const ElideInput& input, gl::Stage stage, const std::string& file,
                               const std::vector<std::string>& source_files) {
  gl::StageSymbols s;
  s.stage = stage;
  s.file = file;
  s.glsl_version = input.preprocessed.version;
  s.glsl_profile = input.preprocessed.profile;
  s.source_files = source_files;
  if (!s.source_files.empty()) s.source_files.front() = file;
  std::string all;
  all += input.sources.text(input.main_file);
  for (const IncludedFile& inc : input.preprocessed.includes) all += input.sources.text(inc.file);
  s.source_hash = source_hash(all);
  const SymbolBuilder builder(input);
  s.symbols = builder.symbols();
  s.specialization_constants = builder.specialization_constants();
  if (input.preprocessed.language.extension_enabled(kVulkanGlslExtension)) s.client = gl::Client::vulkan;
  return s;
}

void add_declarations(gl::SymbolTable& table, const ElideInput& input) {
  const DimensionRegistry& registry = input.checked.registry;
  auto known = [](const auto& list, const std::string& name) {
    for (const auto& item : list)
      if (item.name == name) return true;
    return false;
  };
  for (const ast::Decl* d : input.unit.decls) {
    if (auto* dim = ast::dyn_cast<ast::DimensionDecl>(d)) {
      gl::SourceLocation at = location_of(input.sources, dim->name_range.begin);
      if (dim->definition == nullptr) {
        if (!known(table.base_dimensions, dim->name) && registry.find_base(dim->name))
          table.base_dimensions.push_back({dim->name, at});
      } else if (const DerivedDimension* derived = registry.find_derived(dim->name)) {
        if (!known(table.derived_dimensions, dim->name))
          table.derived_dimensions.push_back({dim->name, exponents_of(derived->value, registry), at});
      }
    } else if (auto* unit = ast::dyn_cast<ast::UnitDecl>(d)) {
      if (const Unit* u = registry.find_unit(unit->name); u && !known(table.units, unit->name)) {
        gl::Dimension dimension{exponents_of(u->dimension, registry), registry.format(u->dimension, Notation::ascii)};
        table.units.push_back({unit->name, dimension, u->scale, location_of(input.sources, unit->name_range.begin)});
      }
    } else if (auto* space = ast::dyn_cast<ast::SpaceDecl>(d)) {
      if (!known(table.spaces, space->name) && registry.find_space(space->name))
        table.spaces.push_back({space->name, location_of(input.sources, space->name_range.begin)});
    }
  }
}

namespace {

struct UsedVocabulary {
  std::set<std::string> names;  // dimensions (base and derived), units and spaces, all in one set

  void add(const gl::ValueType& type) {
    if (!type.dimension.name.empty()) names.insert(type.dimension.name);
    for (const auto& [name, exponent] : type.dimension.exponents) names.insert(name);
    names.insert(type.spaces.begin(), type.spaces.end());
  }
  void add(const gl::Symbol& symbol) {
    add(symbol.type);
    if (symbol.texel) add(*symbol.texel);
    for (const gl::Symbol& member : symbol.members) add(member);
    for (const gl::Symbol& field : symbol.fields) add(field);
  }
  bool has(const std::string& name) const { return names.contains(name); }
};

bool from_prelude(const gl::SourceLocation& at) { return at.file == kBuiltinDir; }

std::string exponents_text(const gl::DimensionExponents& exponents) {
  std::string text;
  for (const auto& [name, exponent] : exponents) text += " " + name + "^" + std::to_string(exponent);
  return text;
}

}  // namespace

void trim_vocabulary(gl::SymbolTable& table) {
  // The prelude's content, without its text: a comment or a reordering changes no table.
  std::vector<std::string> entries;
  for (const auto& base : table.base_dimensions)
    if (from_prelude(base.declared_at)) entries.push_back("dimension " + base.name);
  for (const auto& derived : table.derived_dimensions)
    if (from_prelude(derived.declared_at)) entries.push_back("dimension " + derived.name + " =" + exponents_text(derived.exponents));
  for (const auto& unit : table.units)
    if (from_prelude(unit.declared_at)) {
      std::ostringstream scale;
      scale.precision(17);
      scale << unit.scale;
      entries.push_back("unit " + unit.name + " :" + exponents_text(unit.dimension.exponents) + " = " + scale.str());
    }
  for (const auto& space : table.spaces)
    if (from_prelude(space.declared_at)) entries.push_back("space " + space.name);
  if (entries.empty()) return;
  std::sort(entries.begin(), entries.end());
  std::string content;
  for (const std::string& e : entries) content += e + "\n";
  table.vocabulary = {"safegi/prelude.sgl", source_hash(content)};

  UsedVocabulary used;
  for (const gl::StageSymbols& stage : table.stages) {
    for (const gl::Symbol& symbol : stage.symbols) used.add(symbol);
    for (const gl::SpecializationConstant& constant : stage.specialization_constants) used.add(constant.type);
  }
  // A used unit is read through its bases.
  for (const auto& unit : table.units)
    if (used.has(unit.name))
      for (const auto& [base, exponent] : unit.dimension.exponents) used.names.insert(base);
  auto unused = [&](const auto& entry) { return from_prelude(entry.declared_at) && !used.has(entry.name); };
  // Every derived dimension stays: readers name a host's exponent vectors by them ("the host uses
  // spectrum<irradiance>"), whether the program uses that dimension or not.
  for (const auto& derived : table.derived_dimensions)
    for (const auto& [base, exponent] : derived.exponents) used.names.insert(base);
  std::erase_if(table.base_dimensions, unused);
  std::erase_if(table.units, unused);
  std::erase_if(table.spaces, unused);
  // Where in the prelude an entry stands is no part of the table (a comment there moves it).
  auto unplace = [](auto& list) {
    for (auto& entry : list)
      if (from_prelude(entry.declared_at)) entry.declared_at = {std::string(kBuiltinDir), 0, 0};
  };
  unplace(table.base_dimensions);
  unplace(table.derived_dimensions);
  unplace(table.units);
  unplace(table.spaces);
}

}  // namespace safegi
