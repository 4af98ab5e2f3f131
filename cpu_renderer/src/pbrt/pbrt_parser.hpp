// pbrt-v3 scene files, stage 2: tokens → directives. Knows the grammar of
// every pbrt-v3 directive (its fixed arguments and whether a parameter list
// follows) and of parameter lists ("type name" followed by a value or a
// bracketed list), and follows Include into other files. What a directive
// means is the importer's business (pbrt_importer.cpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pbrt/pbrt_tokenizer.hpp"

namespace safegi::render::pbrt {

enum class ParamType {
  integer, floating, point2, vector2, point3, vector3, normal, rgb, xyz, blackbody, spectrum, string, texture, boolean
};

struct Param {
  ParamType type = ParamType::floating;
  std::string type_name;    // as written: "color", "point", "rgb", ...
  std::string name;
  SourceRange declaration;  // the quoted "type name"
  SourceRange values;       // the value, or the bracketed list
  std::vector<double> numbers;
  std::vector<std::string> strings;  // also bools ("true"/"false") and texture names
  bool is_string = false;   // a spectrum may be numbers or a name (its file is read into `numbers`)
};

struct Directive {
  std::string name;  // "Shape", "Translate", ...
  SourceRange range; // the directive's word
  // Fixed arguments: the numbers of Translate/Rotate/Scale/LookAt/Transform/...,
  // the quoted strings of Shape "sphere", Texture "name" "spectrum" "imagemap", ...
  std::vector<double> numbers;
  std::vector<std::string> strings;
  std::vector<SourceRange> string_ranges;
  SourceRange arguments;  // all fixed arguments
  std::vector<Param> params;
};

// Reads an included file; on failure returns nullopt and sets `error`.
using FileReader = std::function<std::optional<std::string>(const std::filesystem::path&, std::string& error)>;
FileReader disk_reader();

class Parser {
 public:
  // `search_directory`: where relative Include paths resolve (pbrt-v3: the
  // directory of the main scene file, for every Include at any depth).
  Parser(SourceManager& sources, FileId main_file, std::filesystem::path search_directory, FileReader read_file);
  ~Parser();

  // The next directive, or nullopt at the end of the main file. Throws PbrtError.
  std::optional<Directive> next();

  static constexpr int kMaxIncludeDepth = 32;

 private:
  Token take();
  const Token& peek();
  double number(const Token& token);
  std::string quoted(const char* what, const Directive& directive);
  void numbers(Directive& directive, int count, bool bracketed);
  void parameter_list(Directive& directive);
  Param parameter(const Token& declaration);
  void include(const Directive& directive);
  void read_spectrum_file(Param& param);

  SourceManager& sources_;
  std::filesystem::path search_directory_;
  FileReader read_file_;
  std::vector<std::unique_ptr<Tokenizer>> files_;  // the include stack, innermost last
  std::optional<Token> lookahead_;
};

std::string_view param_type_name(ParamType type);

}  // namespace safegi::render::pbrt
