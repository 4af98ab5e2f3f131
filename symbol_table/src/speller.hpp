#pragma once
// C++ spellings of the symbol table's types, for the generated handles
// headers (OpenGL: handles_header.cpp; Vulkan: vk_handles_header.cpp). Internal.
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "safegi/symbol_table/error.hpp"
#include "safegi/symbol_table/handles_header.hpp"

namespace safegi::gl::detail {

inline const std::set<std::string> kTypedBases{"length", "time", "energy", "angle", "solid_angle", "proj"};
inline const std::set<std::string> kTypedSpaces{"world",   "object", "camera", "light",
                                                "shading", "clip",   "ndc",    "raster"};

class Speller {
 public:
  Speller(const HandlesHeaderOptions& options, const DimensionNamer& namer) : options_(options), namer_(namer) {}

  std::string type(const Symbol& symbol, const ValueType& type) const {
    switch (type.kind) {
      case Kind::plain:
        return plain(symbol, type.glsl_type);
      case Kind::scalar:
        return type.dimension.exponents.empty() ? "float" : "safegi::quantity<" + dimension(symbol, type) + '>';
      case Kind::spectrum:
        return "safegi::spectrum<" + dimension(symbol, type) + '>';
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
    fail(symbol, "has GLSL type " + glsl + ", which the typed API cannot bind");
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
      factors.push_back(exponent == 1 ? spelled
                                      : "safegi::dim::pow<" + spelled + ", " + std::to_string(exponent) + '>');
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

// The Vulkan header (vk_handles_header.cpp).
std::string generate_vk_handles_header(const SymbolTable& table, const HandlesHeaderOptions& options);

// What both handle headers write after opening their namespace: the symbols left out, then
// the aliases of the dimensions the handles spell (dimensions::dimension_N).
inline void write_skipped_and_aliases(std::ostream& out, const std::vector<std::string>& skipped, const Speller& speller) {
  for (const auto& note : skipped) out << "// not generated: " << note << '\n';
  if (!skipped.empty()) out << '\n';
  if (speller.dimension_aliases().empty()) return;
  out << "namespace dimensions {\n";
  for (const auto& [alias, product] : speller.dimension_aliases()) out << "using " << alias << " = " << product << ";\n";
  out << "}  // namespace dimensions\n\n";
}

}  // namespace safegi::gl::detail
