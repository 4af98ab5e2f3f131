#include "safegi/symbol_table/handles_header.hpp"

#include <map>
#include <set>
#include <sstream>

#include "safegi/symbol_table/error.hpp"

namespace safegi::gl {
namespace {

const std::set<std::string> kTypedBases{"length", "time", "energy", "angle", "solid_angle", "proj"};
const std::set<std::string> kTypedSpaces{"world", "object", "camera", "light", "shading", "clip", "ndc", "raster"};

class Speller {
 public:
  Speller(const HandlesHeaderOptions& options, const DimensionNamer& namer) : options_(options), namer_(namer) {}

  std::string type(const Symbol& symbol, const ValueType& type) const {
    switch (type.kind) {
      case Kind::plain: return plain(symbol, type.glsl_type);
      case Kind::scalar:
        return type.dimension.exponents.empty() ? "float" : "safegi::quantity<" + dimension(symbol, type) + '>';
      case Kind::spectrum: return "safegi::spectrum<" + dimension(symbol, type) + '>';
      case Kind::vector:
        if (!type.dimension.exponents.empty() && type.dimension.exponents != DimensionExponents{{"length", 1}})
          return "safegi::vector<" + space(symbol, type.spaces.at(0)) + ", " + dimension(symbol, type) + '>';
        [[fallthrough]];
      case Kind::point:
      case Kind::direction:
      case Kind::normal:
      case Kind::hpoint:
        return "safegi::" + std::string(to_string(type.kind)) + '<' + space(symbol, type.spaces.at(0)) + '>';
      case Kind::map:
      case Kind::projective_map:
        return "safegi::" + std::string(to_string(type.kind)) + '<' + space(symbol, type.spaces.at(0)) + ", " +
               space(symbol, type.spaces.at(1)) + '>';
      case Kind::sampler:
      case Kind::block:
        break;
    }
    fail(symbol, "has no C++ value type");
  }

 private:
  [[noreturn]] static void fail(const Symbol& symbol, const std::string& why) {
    throw SymbolTableError(to_string(symbol.declared_at) + ": error: '" + symbol.name + "' " + why);
  }

  std::string plain(const Symbol& symbol, const std::string& glsl) const {
    if (glsl == "float") return "float";
    if (glsl == "int") return "std::int32_t";
    if (glsl == "uint") return "std::uint32_t";
    for (const char* prefix : {"vec", "ivec", "uvec", "mat"})
      if (glsl.rfind(prefix, 0) == 0 && glsl.size() > std::string(prefix).size()) return "glm::" + glsl;
    fail(symbol, "has GLSL type " + glsl + ", which runtime_gl cannot bind");
  }

  std::string named(const Symbol& symbol, const std::string& name, const std::set<std::string>& typed,
                    const std::string& typed_prefix, const char* what) const {
    if (auto found = options_.cpp_names.find(name); found != options_.cpp_names.end()) return found->second;
    if (typed.count(name)) return typed_prefix + name;
    fail(symbol, "uses the " + std::string(what) + " '" + name + "', which has no C++ spelling; pass --cpp " + name +
                     "=<C++ type>");
  }

  // Dimensions are spelled from their exponents (so the C++ type is exactly
  // the shader's) under an alias named as the symbol table names them.
  std::string dimension(const Symbol& symbol, const ValueType& type) const {
    if (type.dimension.exponents.empty()) return "safegi::dim::dimensionless";
    std::vector<std::string> factors;
    for (const auto& [base, exponent] : type.dimension.exponents) {
      std::string spelled = named(symbol, base, kTypedBases, "safegi::dim::", "base dimension");
      factors.push_back(exponent == 1 ? spelled : "safegi::dim::pow<" + spelled + ", " + std::to_string(exponent) + '>');
    }
    std::string product = "safegi::dim::product<";
    for (std::size_t i = 0; i < factors.size(); ++i) product += (i ? ", " : "") + factors[i];
    product += '>';
    std::string alias = namer_.name(type.dimension);
    if (alias.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") != std::string::npos)
      alias = "dimension_" + std::to_string(dimension_aliases_.size());
    dimension_aliases_.emplace(alias, product);
    return "dimensions::" + alias;
  }

 public:
  // alias -> spelled product, for the header's `namespace dimensions`.
  const std::map<std::string, std::string>& dimension_aliases() const { return dimension_aliases_; }

 private:
  mutable std::map<std::string, std::string> dimension_aliases_;

  std::string space(const Symbol& symbol, const std::string& name) const {
    return named(symbol, name, kTypedSpaces, "safegi::spaces::", "space");
  }

  const HandlesHeaderOptions& options_;
  const DimensionNamer& namer_;
};

struct Member {
  std::string handle;  // uniform_id<T>, ...
  std::string type;
  std::string lookup;  // uniform, attribute, ...
  const Symbol* symbol;
};

}  // namespace

std::string generate_handles_header(const SymbolTable& table, const HandlesHeaderOptions& options) {
  const DimensionNamer namer = table.namer();
  const Speller speller(options, namer);
  std::vector<Member> members;
  std::vector<std::string> skipped;
  std::set<std::string> seen;
  for (const auto& stage : table.stages) {
    for (const auto& symbol : stage.symbols) {
      const bool attribute = symbol.storage == Storage::input && stage.stage == Stage::vertex;
      const bool output = symbol.storage == Storage::output && stage.stage == Stage::fragment;
      if (symbol.storage != Storage::uniform && !attribute && !output) continue;  // between stages
      if (!seen.insert(std::string(to_string(symbol.storage)) + ' ' + symbol.name).second) continue;
      if (symbol.type.kind == Kind::block) {
        skipped.push_back(to_string(symbol.declared_at) + ": uniform block " + symbol.name +
                          " (set it through a uniform buffer)");
        continue;
      }
      if (symbol.type.kind == Kind::sampler) {
        if (symbol.type.glsl_type != "sampler2D") {
          skipped.push_back(to_string(symbol.declared_at) + ": " + symbol.type.glsl_type + ' ' + symbol.name +
                            " (only sampler2D binds a texture2d)");
          continue;
        }
        members.push_back({"sampler_id", speller.type(symbol, *symbol.texel), "sampler", &symbol});
        continue;
      }
      const std::string type = speller.type(symbol, symbol.type);
      if (attribute) members.push_back({"attribute_id", type, "attribute", &symbol});
      else if (output) members.push_back({"output_id", type, "output", &symbol});
      else if (symbol.array_size) members.push_back({"uniform_array_id", type, "uniform_array", &symbol});
      else members.push_back({"uniform_id", type, "uniform", &symbol});
    }
  }

  std::ostringstream out;
  out << "// Generated by safegi-gl-handles" << (options.origin.empty() ? "" : " from " + options.origin)
      << ". Do not edit.\n"
         "// Typed handles for one program's interface: giving a handle a value of another\n"
         "// dimension or space than the shader declares fails to compile.\n"
         "#pragma once\n\n"
         "#include <cstdint>\n"
         "#include <safegi/runtime_gl/runtime_gl.hpp>\n"
         "#include <safegi/typed.hpp>\n\n"
         "namespace "
      << options.namespace_name << " {\n\n";
  for (const auto& note : skipped) out << "// not generated: " << note << '\n';
  if (!skipped.empty()) out << '\n';
  if (!speller.dimension_aliases().empty()) {
    out << "namespace dimensions {\n";
    for (const auto& [alias, product] : speller.dimension_aliases()) out << "using " << alias << " = " << product << ";\n";
    out << "}  // namespace dimensions\n\n";
  }
  out << "// The host type of each variable (samplers: of one texel).\n";
  for (const auto& member : members) {
    const Symbol& symbol = *member.symbol;
    out << "// " << to_string(symbol.declared_at) << ": "
        << (symbol.printed_type.empty() ? in_words(symbol.type, namer, symbol.texel ? &*symbol.texel : nullptr)
                                        : symbol.printed_type)
        << ' ' << symbol.name << (symbol.array_size ? '[' + std::to_string(*symbol.array_size) + ']' : "") << '\n'
        << "using " << symbol.name << "_type = " << member.type << ";\n";
  }
  out << "\nstruct " << options.struct_name << " {\n";
  for (const auto& member : members)
    out << "  safegi::gl::" << member.handle << '<' << member.symbol->name << "_type> " << member.symbol->name
        << ";\n";
  out << "\n  // Looks every handle up (checked against the program's symbol table) and\n"
         "  // refuses a program whose sources are not the ones this header was made from.\n"
         "  explicit "
      << options.struct_name << "(const safegi::gl::Program& program)";
  for (std::size_t i = 0; i < members.size(); ++i) {
    const Member& member = members[i];
    out << (i == 0 ? "\n      : " : ",\n        ") << member.symbol->name << "(program." << member.lookup << '<'
        << member.symbol->name << "_type>(\"" << member.symbol->name << "\"))";
  }
  out << " {\n";
  for (const auto& stage : table.stages)
    if (!stage.source_hash.empty())
      out << "    program.expect_source_hash(safegi::gl::Stage::" << to_string(stage.stage) << ", \""
          << stage.source_hash << "\");\n";
  out << "  }\n};\n\n}  // namespace " << options.namespace_name << '\n';
  return out.str();
}

}  // namespace safegi::gl
