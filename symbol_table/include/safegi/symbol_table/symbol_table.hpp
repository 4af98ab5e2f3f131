#pragma once
// The compiler's symbol table (schema v2, docs/symbol-table.md): what every
// shader interface variable is, in GLSL and in SafeGI terms, and where it was
// declared. runtime_gl binds typed host handles by it.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "safegi/symbol_table/value_type.hpp"

namespace safegi::gl {

inline constexpr int kSymbolTableVersion = 2;
// Version 2 added what a Vulkan host binds by (client, set, push_constant,
// packing, offsets and sizes, specialization constants); a v1 table is a v2
// table without them, and is read as one.
inline constexpr int kOldestSymbolTableVersion = 1;

// The stages of stages.def, in its order (the pipeline's); a table names each by its id
// ("tess_control", "ray_generation"), as the checker's Stage does.
enum class Stage {
#define SAFEGI_STAGE(id, ...) id,
#include "safegi/symbol_table/stages.def"
};

std::string_view to_string(Stage stage);
std::optional<Stage> stage_from_string(std::string_view text);

// `buffer`: shader storage blocks. The typed API binds none of them yet, but
// the table lists them so a host tool sees the shader's whole interface.
enum class Storage { uniform, input, output, buffer };

std::string_view to_string(Storage storage);  // "uniform", "in", "out", "buffer"

struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

// "file:line:col" (column omitted when 0).
std::string to_string(const SourceLocation& location);

struct Symbol {
  std::string name;
  Storage storage = Storage::uniform;
  ValueType type;
  std::string printed_type;            // the compiler's own words for the type
  std::optional<ValueType> texel;      // samplers: the value one texel holds
  std::optional<int> array_size;       // arrays: the declared element count
  bool unsized = false;                // arrays whose count the compiler does not know (`flux[]`)
  std::optional<int> location;         // explicit layout(location = N)
  std::optional<int> binding;          // explicit layout(binding = N)
  std::optional<int> set;              // Vulkan: the descriptor set, layout(set = N) or 0
  bool push_constant = false;          // blocks: layout(push_constant)
  bool shader_record = false;          // blocks: layout(shaderRecordEXT), the shader binding table's record
  std::string packing;                 // blocks whose members have offsets: "std140", "std430" or "scalar"
  std::optional<long long> offset;     // members of such blocks: bytes from the block's start
  std::optional<long long> size;       // such blocks (to the end of the last member) and members, in bytes
  std::optional<long long> array_stride;   // array members: bytes from one element to the next
  std::optional<long long> matrix_stride;  // matrix members: bytes from one column (row_major: row) to the next
  bool row_major = false;              // matrix members laid out by rows
  SourceLocation declared_at;
  std::string instance_name;           // blocks: instance name, may be empty
  std::string block;                   // block members: the enclosing block's name
  std::vector<Symbol> members;         // blocks: members in declaration order
  // A member of struct type (or an array of structs) in a block with a known packing: the struct's
  // fields, each placed from the start of the struct (of each element), nested structs likewise.
  std::vector<Symbol> fields;
};

// layout(constant_id = N) const ... (and local_size_x_id, named
// gl_WorkGroupSize.x): a value a Vulkan host sets when it creates the pipeline.
struct SpecializationConstant {
  std::string name;
  int id = 0;
  ValueType type;
  std::string printed_type;
  std::optional<double> default_value;  // the declared one, when the compiler knows it
  SourceLocation declared_at;
};

// Which API the stage was compiled for: OpenGL, or Vulkan (-V, --target-env
// vulkan*: GL_KHR_vulkan_glsl, descriptor sets, push constants).
enum class Client { opengl, vulkan };
std::string_view to_string(Client client);  // "opengl", "vulkan"

struct StageSymbols {
  Stage stage = Stage::vertex;
  Client client = Client::opengl;
  std::string file;                       // the annotated source the stage came from
  int glsl_version = 0;                   // 330, 450, ...
  std::string glsl_profile;               // "core", "compatibility", "es" or empty
  std::vector<std::string> source_files;  // #line source-string number -> file
  std::string source_hash;
  std::vector<Symbol> symbols;
  std::vector<SpecializationConstant> specialization_constants;

  // The interface variable of the given storage and name (blocks are searched
  // by block name; members by "member" and "Block.member").
  const Symbol* find(Storage storage, std::string_view name) const;
  // File name for a driver source-string number (falls back to `file`).
  const std::string& file_for_source_string(int index) const;
};

struct DerivedDimension {
  std::string name;
  DimensionExponents exponents;
  SourceLocation declared_at;
};

struct BaseDimension {
  std::string name;
  SourceLocation declared_at;
};

struct Unit {
  std::string name;
  Dimension dimension;
  double scale = 1.0;  // value of one unit in the dimension's reference unit
  SourceLocation declared_at;
};

struct SpaceDeclaration {
  std::string name;
  SourceLocation declared_at;
};

// The vocabulary a table was checked against, by name and content hash: a table lists
// only the prelude entries its symbols use (and every entry its programs declare).
struct Vocabulary {
  std::string name;  // "safegi/prelude.sgl"
  std::string hash;  // "fnv1a64:…" of the entries' names, exponents and scales (not their text)
};

enum class TableMode { shader, program };

struct SymbolTable {
  int version = kSymbolTableVersion;
  TableMode mode = TableMode::shader;
  std::string compiler;     // producer, e.g. "safeglslc 0.1.0"
  std::string source_hash;  // over all stages' sources
  Vocabulary vocabulary;    // empty when the program includes no prelude
  std::vector<BaseDimension> base_dimensions;
  std::vector<DerivedDimension> derived_dimensions;
  std::vector<Unit> units;
  std::vector<SpaceDeclaration> spaces;
  std::vector<StageSymbols> stages;

  const StageSymbols* stage(Stage which) const;
  DimensionNamer namer() const;
};

// Parses schema v1 and v2. `origin` names the table in messages (a path or
// "<in-memory>"). Throws SymbolTableError: "origin: error: <json pointer>: ...".
SymbolTable parse_symbol_table(std::string_view json_text, std::string_view origin = "<symbol table>");

// The canonical JSON text of a table (what the elider should emit).
std::string to_json(const SymbolTable& table);

}  // namespace safegi::gl
