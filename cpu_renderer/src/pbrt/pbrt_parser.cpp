#include "pbrt/pbrt_parser.hpp"

#include "pbrt/pbrt_colour.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string_view>

namespace safegi::render::pbrt {

namespace {

// What follows each directive's word, as data (pbrt-v3's core/parser.cpp).
enum class Arguments {
  none,            // AttributeBegin, WorldEnd, ...
  numbers,         // Translate 1 2 3: `count` bare numbers
  matrix,          // Transform [ 16 numbers ]
  strings,         // NamedMaterial "name": `count` quoted strings
  strings_params,  // Shape "sphere" "float radius" [1]: `count` strings, then parameters
  word,            // ActiveTransform All|StartTime|EndTime
  medium,          // MediumInterface "inside" ["outside"]
};
struct Grammar {
  std::string_view name;
  Arguments arguments;
  int count;
};
constexpr Grammar kDirectives[] = {
    {"Accelerator", Arguments::strings_params, 1},    {"ActiveTransform", Arguments::word, 1},
    {"AreaLightSource", Arguments::strings_params, 1}, {"AttributeBegin", Arguments::none, 0},
    {"AttributeEnd", Arguments::none, 0},              {"Camera", Arguments::strings_params, 1},
    {"ConcatTransform", Arguments::matrix, 16},        {"CoordinateSystem", Arguments::strings, 1},
    {"CoordSysTransform", Arguments::strings, 1},      {"Film", Arguments::strings_params, 1},
    {"Identity", Arguments::none, 0},                  {"Include", Arguments::strings, 1},
    {"Integrator", Arguments::strings_params, 1},      {"LightSource", Arguments::strings_params, 1},
    {"LookAt", Arguments::numbers, 9},                 {"MakeNamedMaterial", Arguments::strings_params, 1},
    {"MakeNamedMedium", Arguments::strings_params, 1}, {"Material", Arguments::strings_params, 1},
    {"MediumInterface", Arguments::medium, 1},         {"NamedMaterial", Arguments::strings, 1},
    {"ObjectBegin", Arguments::strings, 1},            {"ObjectEnd", Arguments::none, 0},
    {"ObjectInstance", Arguments::strings, 1},         {"PixelFilter", Arguments::strings_params, 1},
    {"ReverseOrientation", Arguments::none, 0},        {"Rotate", Arguments::numbers, 4},
    {"Sampler", Arguments::strings_params, 1},         {"Scale", Arguments::numbers, 3},
    {"Shape", Arguments::strings_params, 1},           {"Texture", Arguments::strings_params, 3},
    {"Transform", Arguments::matrix, 16},              {"TransformBegin", Arguments::none, 0},
    {"TransformEnd", Arguments::none, 0},              {"TransformTimes", Arguments::numbers, 2},
    {"Translate", Arguments::numbers, 3},              {"WorldBegin", Arguments::none, 0},
    {"WorldEnd", Arguments::none, 0},
};
constexpr std::string_view kPbrtV4Only[] = {"Attribute", "ColorSpace", "Option", "Import"};

const Grammar* grammar_of(std::string_view name) {
  for (const Grammar& g : kDirectives)
    if (g.name == name) return &g;
  return nullptr;
}

// Edit distance, for "did you mean" on misspelt directives and types.
size_t distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t substitution = diagonal + (std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                                                   std::tolower(static_cast<unsigned char>(b[j - 1])) ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
    }
  }
  return row[b.size()];
}

struct TypeName {
  std::string_view name;
  ParamType type;
};
constexpr TypeName kParamTypes[] = {
    {"integer", ParamType::integer}, {"float", ParamType::floating},  {"point2", ParamType::point2},
    {"vector2", ParamType::vector2}, {"point3", ParamType::point3},   {"point", ParamType::point3},
    {"vector3", ParamType::vector3}, {"vector", ParamType::vector3},  {"normal", ParamType::normal},
    {"rgb", ParamType::rgb},         {"color", ParamType::rgb},       {"xyz", ParamType::xyz},
    {"blackbody", ParamType::blackbody}, {"spectrum", ParamType::spectrum}, {"string", ParamType::string},
    {"texture", ParamType::texture}, {"bool", ParamType::boolean},
};

std::string type_list() {
  std::string list;
  for (const TypeName& t : kParamTypes) list += (list.empty() ? "" : ", ") + std::string(t.name);
  return list;
}

SourceRange span(SourceRange first, SourceRange last) {
  if (first.begin.file != last.begin.file) return first;
  return {first.begin, last.end};
}

// pbrt-v3's ReadFloatFile: numbers (characters of 0-9 . e + -, starting
// with no e) separated by anything else, '#' comments to the end of the line.
// pbrt-v3 warns about other text and skips it; here it is an error.
bool read_float_file(std::string_view text, std::vector<double>& values, std::string& error) {
  int line = 1;
  auto starts_number = [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+';
  };
  for (size_t i = 0; i < text.size();) {
    char c = text[i];
    if (c == '#') {
      while (i < text.size() && text[i] != '\n') ++i;
    } else if (starts_number(c)) {
      size_t start = i;
      while (i < text.size() && (starts_number(text[i]) || text[i] == 'e')) ++i;
      std::string_view word = text.substr(start, i - start);
      if (word[0] == '+') word.remove_prefix(1);
      double value = 0;
      auto [end, failed] = std::from_chars(word.data(), word.data() + word.size(), value);
      if (failed != std::errc() || end != word.data() + word.size() || !std::isfinite(value)) {
        error = "line " + std::to_string(line) + ": '" + std::string(text.substr(start, i - start)) + "' is not a number";
        return false;
      }
      values.push_back(value);
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      line += c == '\n';
      ++i;
    } else {
      char shown[8];
      std::snprintf(shown, sizeof shown, std::isprint(static_cast<unsigned char>(c)) ? "'%c'" : "byte %02x",
                    static_cast<unsigned char>(c));
      error = "line " + std::to_string(line) + ": " + shown + " is neither a number nor a '#' comment";
      return false;
    }
  }
  return true;
}

}  // namespace

std::string_view param_type_name(ParamType type) {
  for (const TypeName& t : kParamTypes)
    if (t.type == type) return t.name;
  return "?";
}

FileReader disk_reader() {
  return [](const std::filesystem::path& path, std::string& error) -> std::optional<std::string> {
    std::error_code code;
    if (!std::filesystem::is_regular_file(path, code)) {
      error = std::filesystem::exists(path, code) ? "not a regular file" : "no such file";
      return std::nullopt;
    }
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) {
      error = "cannot read it";
      return std::nullopt;
    }
    return std::move(text).str();
  };
}

Parser::Parser(SourceManager& sources, FileId main_file, std::filesystem::path search_directory, FileReader read_file)
    : sources_(sources), search_directory_(std::move(search_directory)), read_file_(std::move(read_file)) {
  files_.push_back(std::make_unique<Tokenizer>(sources_, main_file));
}

Parser::~Parser() = default;

// The next token of the innermost file; at its end, the including file continues.
Token Parser::take() {
  if (lookahead_) {
    Token token = std::move(*lookahead_);
    lookahead_.reset();
    return token;
  }
  while (true) {
    Token token = files_.back()->next();
    if (token.kind != TokenKind::end || files_.size() == 1) return token;
    files_.pop_back();
  }
}

const Token& Parser::peek() {
  if (!lookahead_) lookahead_ = take();
  return *lookahead_;
}

double Parser::number(const Token& token) {
  if (token.kind != TokenKind::word) fail(token.range, "expected a number, found " + describe(token));
  std::string_view text = token.text;
  if (!text.empty() && text[0] == '+') text.remove_prefix(1);
  double value = 0;
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error == std::errc::result_out_of_range)
    fail(token.range, "number " + describe(token) + " is out of range");
  if (error != std::errc() || end != text.data() + text.size() || text.empty())
    fail(token.range, "expected a number, found " + describe(token));
  if (!std::isfinite(value)) fail(token.range, "expected a finite number, found " + describe(token));
  return value;
}

std::string Parser::quoted(const char* what, const Directive& directive) {
  Token token = take();
  if (token.kind != TokenKind::string)
    fail(token.range, std::string("expected ") + what + " (a quoted string) after " + directive.name + ", found " +
                          describe(token));
  return token.text;
}

void Parser::numbers(Directive& directive, int count, bool bracketed) {
  SourceRange first = peek().range, last = first;
  if (bracketed) {
    Token open = take();
    if (open.kind != TokenKind::open_bracket)
      fail(open.range, "expected '[' after " + directive.name + ", found " + describe(open),
           directive.name + " takes [ 16 numbers ], the matrix column by column");
  }
  for (int i = 0; i < count; ++i) {
    Token token = take();
    std::string_view text = token.text;
    bool numeric = token.kind == TokenKind::word && !text.empty() &&
                   (std::isdigit(static_cast<unsigned char>(text[0])) || text[0] == '-' || text[0] == '+' || text[0] == '.');
    if (!numeric)
      fail(token.range, "expected a number (" + directive.name + " takes " + std::to_string(count) + ", this is number " +
                            std::to_string(i + 1) + "), found " + describe(token));
    directive.numbers.push_back(number(token));
    last = token.range;
  }
  if (bracketed) {
    Token close = take();
    if (close.kind != TokenKind::close_bracket)
      fail(close.range, "expected ']' after the 16 numbers of " + directive.name + ", found " + describe(close));
    last = close.range;
  }
  directive.arguments = span(first, last);
}

Param Parser::parameter(const Token& declaration) {
  Param param;
  param.declaration = declaration.range;
  std::istringstream words(declaration.text);
  std::string type, name, extra;
  words >> type >> name >> extra;
  if (type.empty() || name.empty() || !extra.empty())
    fail(declaration.range, "expected a parameter declaration \"type name\" (e.g. \"float radius\"), found " +
                                describe(declaration));
  const TypeName* found = nullptr;
  for (const TypeName& t : kParamTypes)
    if (t.name == type) found = &t;
  if (!found) {
    std::string hint = "pbrt-v3 parameter types: " + type_list();
    for (const TypeName& t : kParamTypes)
      if (distance(type, t.name) <= 2) hint = "did you mean \"" + std::string(t.name) + " " + name + "\"?";
    if (type == "normal3") hint = "pbrt-v4 syntax; pbrt-v3 writes \"normal " + name + "\"";
    fail(declaration.range, "unknown parameter type '" + type + "' in " + describe(declaration), hint);
  }
  param.type = found->type;
  param.type_name = type;
  param.name = name;

  // One value, or a bracketed list of numbers or of strings (not both).
  Token first = take();
  SourceRange last = first.range;
  std::vector<Token> values;
  if (first.kind == TokenKind::open_bracket) {
    while (true) {
      Token token = take();
      if (token.kind == TokenKind::close_bracket) {
        last = token.range;
        break;
      }
      if (token.kind == TokenKind::end)
        fail(first.range, "the list of \"" + declaration.text + "\" is not closed: the file ends before its ']'");
      if (token.kind == TokenKind::open_bracket)
        fail(token.range, "expected a value or ']' in the list of \"" + declaration.text + "\", found '['",
             "lists do not nest");
      values.push_back(std::move(token));
    }
  } else if (first.kind == TokenKind::word || first.kind == TokenKind::string) {
    values.push_back(first);
  } else {
    fail(first.range, "expected a value for \"" + declaration.text + "\", found " + describe(first));
  }
  param.values = span(first.range, last);
  bool wants_strings = param.type == ParamType::string || param.type == ParamType::texture ||
                       param.type == ParamType::boolean;
  if (!values.empty()) param.is_string = values.front().kind == TokenKind::string;
  for (const Token& value : values) {
    bool is_string = value.kind == TokenKind::string;
    if (is_string != param.is_string)
      fail(value.range, "the list of \"" + declaration.text + "\" mixes numbers and strings");
    if (param.type != ParamType::spectrum && is_string != wants_strings)
      fail(value.range, std::string("expected ") + (wants_strings ? "a quoted string" : "a number") + " for \"" +
                            declaration.text + "\", found " + describe(value));
    if (is_string) {
      if (param.type == ParamType::boolean && value.text != "true" && value.text != "false")
        fail(value.range, "expected \"true\" or \"false\" for \"" + declaration.text + "\", found " + describe(value));
      param.strings.push_back(value.text);
    } else {
      param.numbers.push_back(number(value));
    }
  }
  if (param.type == ParamType::spectrum && param.is_string && param.strings.size() == 1 &&
      !is_named_spectrum(param.strings[0]))
    read_spectrum_file(param);
  return param;
}

// pbrt-v3's "spectrum" given as a file name: the file's [wavelength value ...]
// pairs (an .spd file), resolved as Include resolves its files.
void Parser::read_spectrum_file(Param& param) {
  std::filesystem::path path = param.strings[0];
  if (path.is_relative()) path = search_directory_ / path;
  std::string error;
  std::optional<std::string> text = read_file_(path, error);
  if (!text)
    fail(param.values, "cannot read spectrum file '" + path.string() + "': " + error,
         "pbrt-v3 resolves it against the directory of the main scene file (and renders black without it); "
         "named spectra: " + named_spectrum_names());
  std::vector<double> numbers;
  if (!read_float_file(*text, numbers, error)) fail(param.values, "spectrum file '" + path.string() + "', " + error);
  if (numbers.size() % 2 != 0)
    fail(param.values, "spectrum file '" + path.string() + "' holds " + std::to_string(numbers.size()) +
                           " numbers, not [wavelength value ...] pairs",
         "pbrt-v3 would drop the last one");
  param.numbers = std::move(numbers);
  param.strings.clear();
  param.is_string = false;
}

void Parser::parameter_list(Directive& directive) {
  while (peek().kind == TokenKind::string) {
    Token declaration = take();
    directive.params.push_back(parameter(declaration));
  }
}

void Parser::include(const Directive& directive) {
  if (files_.size() > static_cast<size_t>(kMaxIncludeDepth))
    fail(directive.range, "Include nested more than " + std::to_string(kMaxIncludeDepth) + " files deep",
         "does a file include itself?");
  std::filesystem::path path = directive.strings[0];
  if (path.is_relative()) path = search_directory_ / path;
  std::string error;
  std::optional<std::string> text = read_file_(path, error);
  if (!text)
    fail(directive.string_ranges[0], "cannot read included file '" + path.string() + "': " + error,
         "pbrt-v3 resolves Include paths against the directory of the main scene file");
  FileId file = sources_.add_file(path.lexically_normal().string(), std::move(*text));
  sources_.set_included_from(file, span(directive.range, directive.arguments));
  files_.push_back(std::make_unique<Tokenizer>(sources_, file));
}

std::optional<Directive> Parser::next() {
  while (true) {
    Token word = take();
    if (word.kind == TokenKind::end) return std::nullopt;
    if (word.kind != TokenKind::word) {
      std::string hint = word.kind == TokenKind::string
                             ? "a parameter list follows a directive and its quoted name, e.g. Shape \"sphere\" \"float radius\" [1]"
                             : "";
      fail(word.range, "expected a directive (Shape, Material, Translate, ...), found " + describe(word), hint);
    }
    const Grammar* grammar = grammar_of(word.text);
    if (!grammar) {
      std::string hint;
      for (std::string_view v4 : kPbrtV4Only)
        if (word.text == v4) hint = word.text + " is pbrt-v4 syntax; this reader takes pbrt-v3 scenes";
      for (const Grammar& g : kDirectives)
        if (hint.empty() && distance(word.text, g.name) <= 2) hint = "did you mean '" + std::string(g.name) + "'?";
      fail(word.range, "unknown directive " + describe(word), hint);
    }
    Directive directive;
    directive.name = word.text;
    directive.range = word.range;
    directive.arguments = {word.range.end, word.range.end};
    switch (grammar->arguments) {
      case Arguments::none: break;
      case Arguments::numbers: numbers(directive, grammar->count, false); break;
      case Arguments::matrix: numbers(directive, grammar->count, true); break;
      case Arguments::word: {
        Token which = take();
        if (which.kind != TokenKind::word || (which.text != "All" && which.text != "StartTime" && which.text != "EndTime"))
          fail(which.range, "expected All, StartTime or EndTime after ActiveTransform, found " + describe(which));
        directive.strings.push_back(which.text);
        directive.string_ranges.push_back(which.range);
        directive.arguments = which.range;
        break;
      }
      case Arguments::medium:
      case Arguments::strings:
      case Arguments::strings_params: {
        static const char* const kTextureArguments[] = {"the texture's name", "its type (\"spectrum\" or \"float\")",
                                                        "its class (e.g. \"imagemap\")"};
        for (int i = 0; i < grammar->count; ++i) {
          SourceRange at = peek().range;
          const char* what = directive.name == "Texture" ? kTextureArguments[i]
                             : directive.name == "Include" ? "a file name"
                             : grammar->arguments == Arguments::strings_params ? "a type name"
                                                                                : "a name";
          directive.strings.push_back(quoted(what, directive));
          directive.string_ranges.push_back(at);
        }
        if (grammar->arguments == Arguments::medium && peek().kind == TokenKind::string) {
          directive.string_ranges.push_back(peek().range);
          directive.strings.push_back(take().text);
        }
        directive.arguments = span(directive.string_ranges.front(), directive.string_ranges.back());
        if (grammar->arguments == Arguments::strings_params) parameter_list(directive);
        break;
      }
    }
    if (directive.name == "Include") {
      include(directive);
      continue;
    }
    return directive;
  }
}

}  // namespace safegi::render::pbrt
