// A stage's inputs, outputs and interface blocks: which types and qualifiers
// each may have by stage and version (GLSL 4.60 §4.3.4-4.3.9, GLSL 1.10-1.50
// for the older limits, Mesa's ast_to_hir where it is stricter).

#include <string>

#include "checker_impl.hpp"
#include "validation.hpp"

namespace safegi::detail {
namespace {

const VersionGate kIntegerVaryings{130, 300, {"GL_EXT_gpu_shader4"}};
const VersionGate kStructVaryings{150, 300};
const VersionGate kDoubleVaryings{400, 0, {"GL_ARB_gpu_shader_fp64"}};
const VersionGate kUniformBlocks{140, 300, {"GL_ARB_uniform_buffer_object"}};
const VersionGate kInOutBlocks{150, 320, {"GL_EXT_shader_io_blocks", "GL_OES_shader_io_blocks"}};

enum class Direction { none, input, output };

Direction direction_of(const ast::TypeQualifiers& q, Stage stage) {
  if (q.has("in") || q.has("attribute")) return Direction::input;
  if (q.has("out")) return Direction::output;
  if (q.has("varying")) return stage == Stage::vertex ? Direction::output : Direction::input;
  return Direction::none;
}

// Inputs of geometry and tessellation shaders and outputs of tessellation
// control and mesh shaders hold one element per vertex (a mesh shader's
// perprimitiveEXT ones, per primitive): they are arrays (GLSL 4.60 §4.3.4,
// §4.3.6, GL_EXT_mesh_shader), except `patch` ones.
bool per_vertex(Stage stage, bool input, const ast::TypeQualifiers& q) {
  if (q.has("patch")) return false;
  if (input) return stage == Stage::geometry || stage == Stage::tess_control || stage == Stage::tess_evaluation;
  return stage == Stage::tess_control || stage == Stage::mesh;
}

}  // namespace

// The type rules of one input or output declaration (not a block).
static void check_interface_variable(Checker& c, const ast::VariableDecl& d, const Type& base, Stage stage) {
  const Direction dir = direction_of(d.qualifiers, stage);
  if (dir == Direction::none || base.is_error() || d.declarators.empty()) return;
  if (per_vertex(stage, dir == Direction::input, d.qualifiers) && d.declarators.front().name.rfind("gl_", 0) != 0) {
    for (const ast::Declarator& decl : d.declarators) {
      if (dir == Direction::output) c.validation_.per_vertex_outputs.emplace(decl.name, decl.name_range);
      if (!decl.array_dims.empty() || base.is_array()) continue;
      c.reject(decl.name_range, std::string("a ") + stage_name(stage) + " shader " + (dir == Direction::input ? "input" : "output") +
                                    " holds one value per vertex: declare '" + decl.name + "' as an array, e.g. '" + decl.name + "[]'",
               code::E_INTERFACE_TYPE);
      return;
    }
  }
  const SourceRange where = d.declarators.front().name_range;
  const std::string name = d.declarators.front().name;
  const bool vertex_input = stage == Stage::vertex && dir == Direction::input;
  const bool fragment_output = stage == Stage::fragment && dir == Direction::output;
  const std::string role = vertex_input ? "vertex shader input" : fragment_output ? "fragment shader output"
                           : dir == Direction::input ? "shader input" : "shader output";
  if (contains_scalar(base, Scalar::bool_)) {
    c.reject(where, "a " + role + " cannot be bool: '" + name + "' is declared " + glsl_name(base), code::E_INTERFACE_TYPE);
    return;
  }
  if (contains_opaque(base) && !c.allows(kBindlessGate)) {
    c.reject(where, "a " + role + " cannot have an opaque type: '" + name + "' is declared " + glsl_name(base),
             code::E_INTERFACE_TYPE);
    return;
  }
  if (vertex_input || fragment_output) {
    for (const ast::Qualifier& x : d.qualifiers.list) {
      if (x.kind == ast::QualifierKind::Interpolation || is_auxiliary_word(x.word)) {
        c.reject(x.range, "'" + x.word + "' cannot qualify a " + role + " (" +
                              (vertex_input ? "vertex inputs are not interpolated" : "fragment outputs are not interpolated") + ")",
                 code::E_QUALIFIER);
        return;
      }
    }
    if (base.shape == Shape::structure) {
      c.reject(where, "a " + role + " cannot be a struct: '" + name + "' is declared " + glsl_name(base), code::E_INTERFACE_TYPE);
      return;
    }
    if (fragment_output && base.shape == Shape::matrix) {
      c.reject(where, "a fragment shader output cannot be a matrix: '" + name + "' is declared " + glsl_name(base),
               code::E_INTERFACE_TYPE, "write its columns to separate outputs");
      return;
    }
  }
  if (vertex_input && base.is_integer() && !c.allows(kIntegerVaryings)) {
    c.reject(where, "integer vertex shader inputs require " + gate_requirement(kIntegerVaryings, c.language()->es) +
                        ": '" + name + "' is declared " + glsl_name(base),
             code::E_INTERFACE_TYPE);
    return;
  }
  if (vertex_input || fragment_output) return;
  // Between stages (varyings): GLSL 1.10-1.20 pass only floats, structs need 1.50.
  if (base.is_integer() && !c.allows(kIntegerVaryings)) {
    c.reject(where, "integer varyings require " + gate_requirement(kIntegerVaryings, c.language()->es) + ": '" + name +
                        "' is declared " + glsl_name(base),
             code::E_INTERFACE_TYPE);
    return;
  }
  if (base.scalar == Scalar::double_ && !c.allows(kDoubleVaryings)) {
    c.reject(where, "double-precision varyings require " + gate_requirement(kDoubleVaryings, c.language()->es) + ": '" +
                        name + "' is declared " + glsl_name(base),
             code::E_INTERFACE_TYPE);
    return;
  }
  if (base.shape == Shape::structure && !c.allows(kStructVaryings)) {
    c.reject(where, "struct varyings require " + gate_requirement(kStructVaryings, c.language()->es) + ": '" + name +
                        "' is declared " + glsl_name(base),
             code::E_INTERFACE_TYPE);
    return;
  }
  // GLSL 1.30 §4.3.6 (and every version since): integer fragment inputs are not interpolated.
  if (stage == Stage::fragment && dir == Direction::input && (base.is_integer() || base.scalar == Scalar::double_) &&
      !d.qualifiers.has("flat")) {
    c.reject(where, "an integer or double fragment shader input must be 'flat': '" + name + "' is declared " + glsl_name(base),
             code::E_INTERFACE_TYPE, "write 'flat in " + glsl_name(base) + " " + name + "'");
  }
}

void Checker::validate_interface(const ast::VariableDecl& d, const Type& base) {
  check_interface_variable(*this, d, base, options_.stage);
}

void Checker::validate_block(const ast::InterfaceBlockDecl& d, bool layouts) {
  const ast::TypeQualifiers& q = d.qualifiers;
  if (!memory_model_qualifiers(q)) return;
  const char* storage = q.has("uniform") ? "uniform" : q.has("buffer") ? "buffer" : q.has("in") ? "in" : q.has("out") ? "out" : "";
  const std::string storage_word = storage;
  if (storage_word == "in" && options_.stage == Stage::vertex) {
    reject(d.block_name_range, "a vertex shader has no input blocks: vertex inputs are single variables", code::E_INTERFACE_BLOCK);
    return;
  }
  if (storage_word == "out" && options_.stage == Stage::fragment) {
    reject(d.block_name_range, "a fragment shader has no output blocks: fragment outputs are single variables",
           code::E_INTERFACE_BLOCK);
    return;
  }
  if (storage_word == "uniform" && !allows(kUniformBlocks)) {
    reject(d.block_name_range, "uniform blocks require " + gate_requirement(kUniformBlocks, language()->es), code::E_VERSION);
    return;
  }
  if ((storage_word == "in" || storage_word == "out") && !allows(kInOutBlocks)) {
    reject(d.block_name_range, "'" + storage_word + "' blocks require " + gate_requirement(kInOutBlocks, language()->es),
           code::E_VERSION);
    return;
  }
  if (storage_word == "out" && per_vertex(options_.stage, false, q) && !d.instance_name.empty())
    validation_.per_vertex_outputs.emplace(d.instance_name, d.instance_name_range);
  if ((storage_word == "in" || storage_word == "out") && per_vertex(options_.stage, storage_word == "in", q) &&
      d.instance_array_dims.empty()) {
    reject(d.instance_name.empty() ? d.block_name_range : d.instance_name_range,
           std::string("a ") + stage_name(options_.stage) + " shader " + (storage_word == "in" ? "input" : "output") +
               " block holds one value per vertex: give it an array instance, e.g. '} " +
               (d.instance_name.empty() ? std::string("v") : d.instance_name) + "[];'",
           code::E_INTERFACE_BLOCK);
    return;
  }
  // The built-in blocks a shader may redeclare: gl_PerVertex, and a mesh shader's vertex and primitive blocks.
  const bool builtin_block = d.block_name == "gl_PerVertex" || d.block_name == "gl_MeshPerVertexNV" ||
                             d.block_name == "gl_MeshPerVertexEXT" || d.block_name == "gl_MeshPerPrimitiveNV" ||
                             d.block_name == "gl_MeshPerPrimitiveEXT";
  if (d.block_name.rfind("gl_", 0) == 0 && !builtin_block) {
    reject(d.block_name_range, "block name '" + d.block_name + "' begins with 'gl_', which is reserved", code::E_RESERVED_NAME);
    return;
  }
  if (d.instance_name.rfind("gl_", 0) == 0 && !builtin_block) {
    reject(d.instance_name_range, "instance name '" + d.instance_name + "' begins with 'gl_', which is reserved",
           code::E_RESERVED_NAME);
    return;
  }
  for (const ast::VariableDecl* member : d.members) {
    if (member->type && member->type->form == ast::TypeSpecifier::Form::Struct) {
      reject(member->type->range, "a struct cannot be defined inside a block", code::E_INTERFACE_BLOCK,
             "define the struct at global scope and use its name");
      return;
    }
    if (!memory_model_qualifiers(member->qualifiers)) return;
    for (const ast::Qualifier& x : member->qualifiers.list) {
      if (!is_storage_word(x.word) || x.word == storage_word) continue;
      reject(x.range, "member storage '" + x.word + "' contradicts the block's '" + storage_word + "'", code::E_INTERFACE_BLOCK);
      return;
    }
    for (const ast::Declarator& decl : member->declarators) {
      if (!d.instance_name.empty() && member->qualifiers.has("readonly"))
        validation_.readonly_members.emplace(d.instance_name + "." + decl.name, decl.name_range);
      if (decl.name.rfind("gl_", 0) == 0 && !builtin_block) {
        reject(decl.name_range, "member name '" + decl.name + "' begins with 'gl_', which is reserved", code::E_RESERVED_NAME);
        return;
      }
    }
    for (const ast::Declarator& decl : member->declarators) {
      const Type* t = result_.type_of(&decl);  // block_decl resolved it
      if (!t || !contains_opaque(*t) || allows(kBindlessGate)) continue;
      reject(decl.name_range, "a block member cannot have an opaque type ('" + glsl_name(*t) + "')", code::E_INTERFACE_BLOCK,
             "declare it as a separate uniform");
      return;
    }
  }
  if (layouts) validate_block_layouts(d);
}

}  // namespace safegi::detail
