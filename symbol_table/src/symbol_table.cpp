#include "safegi/symbol_table/symbol_table.hpp"

#include <array>
#include <nlohmann/json.hpp>
#include <utility>

#include "safegi/symbol_table/error.hpp"

namespace safegi::gl {
namespace {

using nlohmann::json;

constexpr std::pair<Stage, std::string_view> kStageNames[] = {
#define SAFEGI_STAGE(id, ...) {Stage::id, #id},
#include "safegi/symbol_table/stages.def"
};

std::string_view json_type_name(const json& value) {
  if (value.is_number_integer()) return "integer";
  return value.type_name();
}

// A JSON node together with its JSON pointer, so every complaint says where.
class Node {
 public:
  Node(const json& value, std::string pointer, std::string_view origin)
      : value_(value), pointer_(std::move(pointer)), origin_(origin) {}

  [[noreturn]] void fail(const std::string& message) const {
    throw SymbolTableError(std::string(origin_) + ": error: " + (pointer_.empty() ? "/" : pointer_) + ": " +
                           message);
  }
  void expect(bool ok, std::string_view expected) const {
    if (!ok) fail("expected " + std::string(expected) + ", found " + std::string(json_type_name(value_)));
  }

  bool has(const char* key) const { return value_.contains(key) && !value_.at(key).is_null(); }
  Node at(const char* key) const {
    expect(value_.is_object(), "an object");
    if (!value_.contains(key)) fail(std::string("missing required member \"") + key + '"');
    return child(value_.at(key), std::string("/") + key);
  }
  std::vector<Node> elements() const {
    expect(value_.is_array(), "an array");
    std::vector<Node> nodes;
    for (std::size_t i = 0; i < value_.size(); ++i) nodes.push_back(child(value_[i], '/' + std::to_string(i)));
    return nodes;
  }
  std::vector<std::pair<std::string, Node>> members() const {
    expect(value_.is_object(), "an object");
    std::vector<std::pair<std::string, Node>> nodes;
    for (const auto& [key, item] : value_.items()) nodes.emplace_back(key, child(item, '/' + key));
    return nodes;
  }

  std::string string() const {
    expect(value_.is_string(), "a string");
    return value_.get<std::string>();
  }
  int integer() const {
    expect(value_.is_number_integer(), "an integer");
    return value_.get<int>();
  }
  bool boolean() const {
    expect(value_.is_boolean(), "a boolean");
    return value_.get<bool>();
  }
  double number() const {
    expect(value_.is_number(), "a number");
    return value_.get<double>();
  }
  std::string optional_string(const char* key) const { return has(key) ? at(key).string() : std::string(); }
  std::optional<int> optional_integer(const char* key) const {
    return has(key) ? std::optional<int>(at(key).integer()) : std::nullopt;
  }
  std::optional<long long> optional_bytes(const char* key) const {
    if (!has(key)) return std::nullopt;
    Node bytes = at(key);
    bytes.expect(bytes.value_.is_number_integer(), "an integer");
    if (bytes.value_.is_number_unsigned() ? bytes.value_.get<unsigned long long>() > (1ull << 62)
                                          : bytes.value_.get<long long>() < 0)
      bytes.fail("a byte count from 0 to 2^62");
    return bytes.value_.get<long long>();
  }
  std::optional<double> optional_number(const char* key) const {
    return has(key) ? std::optional<double>(at(key).number()) : std::nullopt;
  }

 private:
  Node child(const json& value, const std::string& step) const { return Node(value, pointer_ + step, origin_); }

  const json& value_;
  std::string pointer_;
  std::string_view origin_;
};

SourceLocation read_location(const Node& node) {
  // A prelude entry is named by its file alone: the vocabulary's hash identifies its text.
  return {node.at("file").string(), node.has("line") ? node.at("line").integer() : 0,
          node.has("column") ? node.at("column").integer() : 0};
}

DimensionExponents read_exponents(const Node& node) {
  DimensionExponents exponents;
  for (const auto& [base, exponent] : node.members()) {
    int value = exponent.integer();
    if (value != 0) exponents[base] = value;
  }
  return exponents;
}

Dimension read_dimension(const Node& node) {
  return {read_exponents(node.at("exponents")), node.optional_string("name")};
}

std::vector<std::string> read_strings(const Node& node) {
  std::vector<std::string> strings;
  for (const auto& element : node.elements()) strings.push_back(element.string());
  return strings;
}

ValueType read_value_type(const Node& node) {
  ValueType type;
  Node kind = node.at("kind");
  auto parsed = kind_from_string(kind.string());
  if (!parsed) kind.fail("unknown kind \"" + kind.string() + '"');
  type.kind = *parsed;
  type.glsl_type = node.at("glsl_type").string();
  if (node.has("dimension")) type.dimension = read_dimension(node.at("dimension"));
  if (node.has("spaces")) type.spaces = read_strings(node.at("spaces"));
  std::size_t wanted_spaces = 0;
  switch (type.kind) {
    case Kind::point: case Kind::vector: case Kind::direction: case Kind::normal: case Kind::hpoint:
      wanted_spaces = 1;
      break;
    case Kind::map: case Kind::projective_map:
      wanted_spaces = 2;
      break;
    default:
      break;
  }
  if (type.spaces.size() != wanted_spaces)
    node.fail("a " + std::string(to_string(type.kind)) + " needs " + std::to_string(wanted_spaces) +
              " space(s), found " + std::to_string(type.spaces.size()));
  return type;
}

Storage read_storage(const Node& node) {
  std::string text = node.string();
  if (text == "uniform") return Storage::uniform;
  if (text == "in") return Storage::input;
  if (text == "out") return Storage::output;
  if (text == "buffer") return Storage::buffer;
  node.fail("unknown storage \"" + text + "\" (expected uniform, in, out or buffer)");
}

Symbol read_symbol(const Node& node, Storage storage) {
  Symbol symbol;
  symbol.name = node.at("name").string();
  symbol.storage = storage;
  symbol.type = read_value_type(node);
  symbol.printed_type = node.optional_string("type");
  if (node.has("texel")) symbol.texel = read_value_type(node.at("texel"));
  if (symbol.type.kind == Kind::sampler && !symbol.texel) node.fail("a sampler needs a \"texel\" type");
  symbol.array_size = node.optional_integer("array_size");
  if (symbol.array_size && *symbol.array_size <= 0) node.at("array_size").fail("array size must be positive");
  symbol.unsized = node.has("unsized") && node.at("unsized").boolean();
  if (symbol.unsized && symbol.array_size) node.at("unsized").fail("an unsized array has no \"array_size\"");
  symbol.location = node.optional_integer("location");
  symbol.binding = node.optional_integer("binding");
  symbol.set = node.optional_integer("set");
  symbol.push_constant = node.has("push_constant") && node.at("push_constant").boolean();
  symbol.shader_record = node.has("shader_record") && node.at("shader_record").boolean();
  symbol.packing = node.optional_string("packing");
  if (!symbol.packing.empty() && symbol.packing != "std140" && symbol.packing != "std430" && symbol.packing != "scalar")
    node.at("packing").fail("unknown packing \"" + symbol.packing + "\" (expected std140, std430 or scalar)");
  symbol.offset = node.optional_bytes("offset");
  symbol.size = node.optional_bytes("size");
  symbol.array_stride = node.optional_bytes("array_stride");
  symbol.matrix_stride = node.optional_bytes("matrix_stride");
  symbol.row_major = node.has("row_major") && node.at("row_major").boolean();
  symbol.declared_at = read_location(node.at("declared_at"));
  symbol.instance_name = node.optional_string("instance_name");
  if (symbol.type.kind == Kind::block) {
    for (const auto& member : node.at("members").elements()) {
      symbol.members.push_back(read_symbol(member, storage));
      symbol.members.back().block = symbol.name;
    }
  } else if (node.has("members")) {
    node.at("members").fail("only a block has members");
  }
  if (node.has("fields"))
    for (const auto& field : node.at("fields").elements()) symbol.fields.push_back(read_symbol(field, storage));
  return symbol;
}

StageSymbols read_stage(const Node& node) {
  StageSymbols stage;
  Node name = node.at("stage");
  auto parsed = stage_from_string(name.string());
  if (!parsed) name.fail("unknown stage \"" + name.string() + '"');
  stage.stage = *parsed;
  stage.file = node.at("file").string();
  Node glsl = node.at("glsl_version");
  stage.glsl_version = glsl.at("number").integer();
  stage.glsl_profile = glsl.optional_string("profile");
  if (node.has("source_files")) stage.source_files = read_strings(node.at("source_files"));
  stage.source_hash = node.optional_string("source_hash");
  if (node.has("client")) {
    Node client = node.at("client");
    if (client.string() == "vulkan") stage.client = Client::vulkan;
    else if (client.string() != "opengl") client.fail("expected \"opengl\" or \"vulkan\"");
  }
  for (const auto& symbol : node.at("symbols").elements())
    stage.symbols.push_back(read_symbol(symbol, read_storage(symbol.at("storage"))));
  if (node.has("specialization_constants"))
    for (const auto& constant : node.at("specialization_constants").elements()) {
      SpecializationConstant c;
      c.name = constant.at("name").string();
      c.id = constant.at("id").integer();
      if (c.id < 0) constant.at("id").fail("a constant id is not negative");
      c.type = read_value_type(constant);
      c.printed_type = constant.optional_string("type");
      c.default_value = constant.optional_number("default");
      c.declared_at = read_location(constant.at("declared_at"));
      stage.specialization_constants.push_back(std::move(c));
    }
  return stage;
}

std::string_view mode_name(TableMode mode) { return mode == TableMode::program ? "program" : "shader"; }

}  // namespace

std::string_view to_string(Stage stage) {
  for (const auto& [s, name] : kStageNames)
    if (s == stage) return name;
  return "?";
}

std::optional<Stage> stage_from_string(std::string_view text) {
  for (const auto& [stage, name] : kStageNames)
    if (name == text) return stage;
  return std::nullopt;
}

std::string_view to_string(Client client) { return client == Client::vulkan ? "vulkan" : "opengl"; }

std::string_view to_string(Storage storage) {
  switch (storage) {
    case Storage::uniform: return "uniform";
    case Storage::input: return "in";
    case Storage::output: return "out";
    case Storage::buffer: return "buffer";
  }
  return "?";
}

std::string to_string(const SourceLocation& location) {
  std::string text = location.file + ':' + std::to_string(location.line);
  if (location.column > 0) text += ':' + std::to_string(location.column);
  return text;
}

const Symbol* StageSymbols::find(Storage storage, std::string_view name) const {
  for (const auto& symbol : symbols) {
    if (symbol.storage != storage) continue;
    if (symbol.name == name) return &symbol;
    if (symbol.type.kind != Kind::block) continue;
    for (const auto& member : symbol.members) {
      if (member.name == name || symbol.name + '.' + member.name == name) return &member;
    }
  }
  return nullptr;
}

const std::string& StageSymbols::file_for_source_string(int index) const {
  if (index >= 0 && static_cast<std::size_t>(index) < source_files.size()) return source_files[index];
  return file;
}

const StageSymbols* SymbolTable::stage(Stage which) const {
  for (const auto& s : stages)
    if (s.stage == which) return &s;
  return nullptr;
}

DimensionNamer SymbolTable::namer() const {
  DimensionNamer namer;
  for (const auto& derived : derived_dimensions) namer.add(derived.name, derived.exponents);
  return namer;
}

SymbolTable parse_symbol_table(std::string_view json_text, std::string_view origin) {
  json document;
  try {
    document = json::parse(json_text.begin(), json_text.end());
  } catch (const json::parse_error& error) {
    throw SymbolTableError(std::string(origin) + ": error: not valid JSON: " + error.what());
  }
  Node root(document, "", origin);
  root.expect(document.is_object(), "an object");
  if (root.at("format").string() != "safegi-symbol-table")
    root.at("format").fail("expected \"safegi-symbol-table\"");
  SymbolTable table;
  table.version = root.at("version").integer();
  if (table.version < kOldestSymbolTableVersion || table.version > kSymbolTableVersion)
    root.at("version").fail("unsupported version " + std::to_string(table.version) + " (this runtime reads " +
                            std::to_string(kOldestSymbolTableVersion) + " to " + std::to_string(kSymbolTableVersion) + ')');
  Node mode = root.at("mode");
  if (mode.string() == "program") table.mode = TableMode::program;
  else if (mode.string() != "shader") mode.fail("expected \"shader\" or \"program\"");
  table.compiler = root.optional_string("compiler");
  table.source_hash = root.optional_string("source_hash");
  if (root.has("vocabulary")) {
    Node vocabulary = root.at("vocabulary");
    table.vocabulary = {vocabulary.at("name").string(), vocabulary.at("hash").string()};
  }
  if (root.has("dimensions")) {
    Node dimensions = root.at("dimensions");
    if (dimensions.has("base"))
      for (const auto& base : dimensions.at("base").elements())
        table.base_dimensions.push_back({base.at("name").string(), read_location(base.at("declared_at"))});
    if (dimensions.has("derived"))
      for (const auto& derived : dimensions.at("derived").elements())
        table.derived_dimensions.push_back({derived.at("name").string(), read_exponents(derived.at("exponents")),
                                            read_location(derived.at("declared_at"))});
  }
  if (root.has("units"))
    for (const auto& unit : root.at("units").elements())
      table.units.push_back({unit.at("name").string(), read_dimension(unit.at("dimension")),
                             unit.at("scale").number(), read_location(unit.at("declared_at"))});
  if (root.has("spaces"))
    for (const auto& space : root.at("spaces").elements())
      table.spaces.push_back({space.at("name").string(), read_location(space.at("declared_at"))});
  for (const auto& stage : root.at("stages").elements()) {
    table.stages.push_back(read_stage(stage));
    for (std::size_t i = 0; i + 1 < table.stages.size(); ++i)
      if (table.stages[i].stage == table.stages.back().stage)
        stage.at("stage").fail("stage \"" + std::string(to_string(table.stages.back().stage)) + "\" appears twice");
  }
  if (table.mode == TableMode::shader && table.stages.size() != 1)
    root.at("stages").fail("a shader-mode table has exactly one stage, found " + std::to_string(table.stages.size()));
  return table;
}

// ---- writing ---------------------------------------------------------------

namespace {

json write_location(const SourceLocation& location) {
  json node{{"file", location.file}};
  if (location.line > 0) node["line"] = location.line;
  if (location.column > 0) node["column"] = location.column;
  return node;
}

json write_exponents(const DimensionExponents& exponents) {
  json node = json::object();
  for (const auto& [base, exponent] : exponents) node[base] = exponent;
  return node;
}

json write_dimension(const Dimension& dimension) {
  json node{{"exponents", write_exponents(dimension.exponents)}};
  if (!dimension.name.empty()) node["name"] = dimension.name;
  return node;
}

void write_value_type(json& node, const ValueType& type) {
  node["kind"] = to_string(type.kind);
  node["glsl_type"] = type.glsl_type;
  const bool dimensioned = type.kind == Kind::scalar || type.kind == Kind::spectrum;
  if (dimensioned || (type.kind == Kind::vector && !type.dimension.exponents.empty()))
    node["dimension"] = write_dimension(type.dimension);
  if (!type.spaces.empty()) node["spaces"] = type.spaces;
}

json write_symbol(const Symbol& symbol) {
  json node{{"name", symbol.name}, {"storage", to_string(symbol.storage)}};
  write_value_type(node, symbol.type);
  if (!symbol.printed_type.empty()) node["type"] = symbol.printed_type;
  if (symbol.texel) write_value_type(node["texel"], *symbol.texel);
  if (symbol.array_size) node["array_size"] = *symbol.array_size;
  if (symbol.unsized) node["unsized"] = true;
  if (symbol.location) node["location"] = *symbol.location;
  if (symbol.binding) node["binding"] = *symbol.binding;
  if (symbol.set) node["set"] = *symbol.set;
  if (symbol.push_constant) node["push_constant"] = true;
  if (symbol.shader_record) node["shader_record"] = true;
  if (!symbol.packing.empty()) node["packing"] = symbol.packing;
  if (symbol.offset) node["offset"] = *symbol.offset;
  if (symbol.size) node["size"] = *symbol.size;
  if (symbol.array_stride) node["array_stride"] = *symbol.array_stride;
  if (symbol.matrix_stride) node["matrix_stride"] = *symbol.matrix_stride;
  if (symbol.row_major) node["row_major"] = true;
  if (!symbol.instance_name.empty()) node["instance_name"] = symbol.instance_name;
  if (symbol.type.kind == Kind::block) {
    node["members"] = json::array();
    for (const auto& member : symbol.members) node["members"].push_back(write_symbol(member));
  }
  if (!symbol.fields.empty()) {
    node["fields"] = json::array();
    for (const auto& field : symbol.fields) node["fields"].push_back(write_symbol(field));
  }
  node["declared_at"] = write_location(symbol.declared_at);
  return node;
}

}  // namespace

std::string to_json(const SymbolTable& table) {
  json root{{"format", "safegi-symbol-table"}, {"version", table.version}, {"mode", mode_name(table.mode)}};
  if (!table.compiler.empty()) root["compiler"] = table.compiler;
  if (!table.source_hash.empty()) root["source_hash"] = table.source_hash;
  if (!table.vocabulary.name.empty())
    root["vocabulary"] = {{"name", table.vocabulary.name}, {"hash", table.vocabulary.hash}};
  json& dimensions = root["dimensions"];
  dimensions["base"] = json::array();
  for (const auto& base : table.base_dimensions)
    dimensions["base"].push_back({{"name", base.name}, {"declared_at", write_location(base.declared_at)}});
  dimensions["derived"] = json::array();
  for (const auto& derived : table.derived_dimensions)
    dimensions["derived"].push_back({{"name", derived.name},
                                     {"exponents", write_exponents(derived.exponents)},
                                     {"declared_at", write_location(derived.declared_at)}});
  root["units"] = json::array();
  for (const auto& unit : table.units)
    root["units"].push_back({{"name", unit.name},
                             {"dimension", write_dimension(unit.dimension)},
                             {"scale", unit.scale},
                             {"declared_at", write_location(unit.declared_at)}});
  root["spaces"] = json::array();
  for (const auto& space : table.spaces)
    root["spaces"].push_back({{"name", space.name}, {"declared_at", write_location(space.declared_at)}});
  root["stages"] = json::array();
  for (const auto& stage : table.stages) {
    json node{{"stage", to_string(stage.stage)}, {"file", stage.file}};
    if (stage.client != Client::opengl) node["client"] = to_string(stage.client);
    node["glsl_version"] = {{"number", stage.glsl_version}};
    if (!stage.glsl_profile.empty()) node["glsl_version"]["profile"] = stage.glsl_profile;
    if (!stage.source_files.empty()) node["source_files"] = stage.source_files;
    if (!stage.source_hash.empty()) node["source_hash"] = stage.source_hash;
    node["symbols"] = json::array();
    for (const auto& symbol : stage.symbols) node["symbols"].push_back(write_symbol(symbol));
    if (!stage.specialization_constants.empty()) {
      json& constants = node["specialization_constants"] = json::array();
      for (const auto& constant : stage.specialization_constants) {
        json c{{"name", constant.name}, {"id", constant.id}};
        write_value_type(c, constant.type);
        if (!constant.printed_type.empty()) c["type"] = constant.printed_type;
        const bool integral = constant.type.glsl_type == "int" || constant.type.glsl_type == "uint";
        if (constant.default_value && integral) c["default"] = static_cast<long long>(*constant.default_value);
        else if (constant.default_value) c["default"] = *constant.default_value;
        c["declared_at"] = write_location(constant.declared_at);
        constants.push_back(std::move(c));
      }
    }
    root["stages"].push_back(std::move(node));
  }
  return root.dump(2) + '\n';
}

}  // namespace safegi::gl
