// The directives other than conditionals: #define, #undef, #version,
// #extension, #pragma, #line, #error and #include.

#include <algorithm>
#include <filesystem>
#include <string>

#include <safegi/diagnostics/codes.hpp>
#include <safegi/diagnostics/file.hpp>
#include <safegi/lexer/extensions.hpp>

#include "preprocessor_impl.hpp"

namespace safegi::detail {
namespace {


std::optional<std::string> read_from_disk(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  return read_file(path);
}

bool is_known_version(int v) {
  switch (v) {
    case 100: case 110: case 120: case 130: case 140: case 150: case 300: case 310: case 320:
    case 330: case 400: case 410: case 420: case 430: case 440: case 450: case 460: return true;
    default: return false;
  }
}

}  // namespace

// ------------------------------------------------------------ #define ---

void Preprocessor::directive_define(FileState& f, const Token& hash) {
  std::vector<Token> line = read_directive_line(f, DirectiveKind::define, hash);
  if (line.empty()) {
    error(code::E_DIRECTIVE, directive_range(hash, line), "macro name missing in #define");
    return;
  }
  if (!check_macro_name(line[0], true, f.is_command_line)) return;
  auto macro = std::make_unique<Macro>();
  macro->name = line[0].text;
  macro->name_range = line[0].range;
  std::size_t i = 1;
  if (i < line.size() && line[i].kind == TokenKind::l_paren && !line[i].leading_space) {
    macro->function_like = true;
    ++i;
    bool closed = false;
    if (i < line.size() && line[i].kind == TokenKind::r_paren) {
      ++i;
      closed = true;
    }
    while (!closed) {
      if (i >= line.size() || line[i].kind != TokenKind::identifier) {
        error(code::E_MACRO, i < line.size() ? line[i].range : line.back().range,
              "expected a parameter name in macro parameter list");
        return;
      }
      if (macro->param_index(line[i].text) >= 0) {
        error(code::E_MACRO, line[i].range, "duplicate macro parameter '" + std::string(line[i].text) + "'");
        return;
      }
      macro->params.push_back(line[i].text);
      ++i;
      if (i < line.size() && line[i].kind == TokenKind::comma) {
        ++i;
      } else if (i < line.size() && line[i].kind == TokenKind::r_paren) {
        ++i;
        closed = true;
      } else {
        error(code::E_MACRO, i < line.size() ? line[i].range : line.back().range,
              "expected ',' or ')' in macro parameter list");
        return;
      }
    }
  }
  macro->body.assign(line.begin() + static_cast<std::ptrdiff_t>(i), line.end());
  const auto& body = macro->body;
  if (!body.empty() && (body.front().kind == TokenKind::hash_hash || body.back().kind == TokenKind::hash_hash)) {
    // C rejects the definition; glslang (and so shaders in the wild) only
    // rejects a use, so this warns here and expand_macro() errs on a use.
    const Token& bad = body.front().kind == TokenKind::hash_hash ? body.front() : body.back();
    diagnostics_.report(Diagnostic::warning(bad.range, "'##' cannot appear at either end of a macro body")
                            .with_code(code::W_MACRO)
                            .with_hint("using this macro is an error"));
    macro->paste_at_edge = bad.range;
  }
  for (const Token& t : body) {
    if (t.kind == TokenKind::hash) {
      diagnostics_.report(Diagnostic::error(t.range, "'#' is not allowed in a macro body")
                              .with_code(code::E_MACRO)
                              .with_hint("GLSL has no stringizing operator; only '##' (token pasting) is supported"));
      return;
    }
  }
  auto it = macros_.find(macro->name);
  if (it != macros_.end()) {
    if (!it->second->same_definition(*macro)) {
      Diagnostic d = Diagnostic::error(macro->name_range, "'" + std::string(macro->name) + "' macro redefined")
                         .with_code(code::E_MACRO);
      if (it->second->name_range.valid()) d.with_note(Diagnostic::note(it->second->name_range, "previous definition is here"));
      diagnostics_.report(std::move(d));
    }
    return;  // an identical redefinition changes nothing
  }
  std::string_view key = macro->name;
  add_macro(key, std::move(macro));
}

void Preprocessor::directive_undef(FileState& f, const Token& hash) {
  std::vector<Token> line = read_directive_line(f, DirectiveKind::undef, hash);
  if (line.empty()) {
    error(code::E_DIRECTIVE, directive_range(hash, line), "macro name missing in #undef");
    return;
  }
  if (!check_macro_name(line[0], false, f.is_command_line)) return;
  extra_tokens_warning(line, 1, "undef");
  macros_.erase(line[0].text);
}

// ------------------------------------------------ version, extensions ---

void Preprocessor::directive_version(FileState& f, const Token& hash) {
  std::vector<Token> line = read_directive_line(f, DirectiveKind::version, hash);
  SourceRange directive = directive_range(hash, line);
  if (!f.is_main) {
    error(code::E_VERSION_DIRECTIVE, directive, "#version is only allowed in the main file, not in an included file");
    return;
  }
  if (unit_.version_given) {
    diagnostics_.report(Diagnostic::error(directive, "#version may appear only once")
                            .with_code(code::E_VERSION_DIRECTIVE)
                            .with_note(Diagnostic::note(unit_.version_range, "first #version is here")));
    return;
  }
  if (saw_content_) {
    error(code::E_VERSION_DIRECTIVE, directive,
          "#version must come first in a shader, before anything but comments and white space");
    return;
  }
  if (line.empty() || line[0].kind != TokenKind::int_literal) {
    error(code::E_VERSION_DIRECTIVE, line.empty() ? directive : line[0].range,
          "expected a version number after #version");
    return;
  }
  auto number = integer_literal_value(line[0].text);
  int version = number && *number <= 1000 ? static_cast<int>(*number) : 0;
  if (!is_known_version(version)) {
    error(code::E_VERSION_DIRECTIVE, line[0].range,
          "unknown GLSL version " + std::string(line[0].text) +
              " (expected 100, 110 ... 150, 300, 310, 320, or 330 ... 460)");
    return;
  }
  std::string profile;
  if (line.size() > 1) {
    if (line[1].kind != TokenKind::identifier ||
        (line[1].text != "es" && line[1].text != "core" && line[1].text != "compatibility")) {
      error(code::E_VERSION_DIRECTIVE, line[1].range,
            "unknown profile '" + std::string(line[1].text) + "' (expected 'core', 'compatibility' or 'es')");
      return;
    }
    profile = line[1].text;
    extra_tokens_warning(line, 2, "version");
  }
  bool es_version = version == 100 || version == 300 || version == 310 || version == 320;
  if (es_version && version != 100 && profile != "es") {
    error(code::E_VERSION_DIRECTIVE, directive, "#version " + std::to_string(version) + " requires the 'es' profile");
    return;
  }
  if (!es_version && profile == "es") {
    error(code::E_VERSION_DIRECTIVE, line[1].range, "the 'es' profile requires version 300, 310 or 320");
    return;
  }
  if (!profile.empty() && profile != "es" && version < 150) {
    error(code::E_VERSION_DIRECTIVE, line[1].range, "profiles are only allowed from #version 150 on");
    return;
  }
  if (options_.override_version == 0) {
    unit_.version = version;
    unit_.profile = profile;
    unit_.es = es_version;
  } else if (!unit_.es && unit_.version >= 150 && profile != "es") {
    unit_.profile = profile;  // an overriding desktop version keeps the line's core/compatibility
  }
  unit_.version_given = true;
  unit_.version_range = directive;
  apply_version();
}

void Preprocessor::define_predefined(std::string_view name, std::string_view value, Macro::Builtin builtin) {
  if (macros_.count(name)) return;
  auto m = std::make_unique<Macro>();
  m->name = name;
  m->predefined = true;
  m->builtin = builtin;
  if (!value.empty()) {
    Token t;
    t.kind = TokenKind::int_literal;
    t.text = value;
    m->body.push_back(t);
  }
  add_macro(name, std::move(m));
}

void Preprocessor::apply_version() {
  if (version_applied_) return;
  version_applied_ = true;
  unit_.keywords.version = unit_.version;
  unit_.keywords.es = unit_.es;
  unit_.language.version = unit_.version;
  unit_.language.es = unit_.es;
  unit_.language.compatibility = unit_.profile == "compatibility";
  define_predefined("__LINE__", "", Macro::Builtin::line);
  define_predefined("__FILE__", "", Macro::Builtin::file);
  define_predefined("__VERSION__", save(std::to_string(unit_.version)));
  for (const std::string& extension : options_.extension_macros) define_predefined(save(extension), "1");
  if (options_.vulkan != 0) {
    define_predefined("VULKAN", save(std::to_string(options_.vulkan)));
    unit_.keywords.extension_groups |= extension_groups_enabled_by(kVulkanGlslExtension);
    unit_.language.extensions.emplace_back(kVulkanGlslExtension);
  }
  if (unit_.es) {
    define_predefined("GL_ES", "1");
    define_predefined("GL_es_profile", "1");
    define_predefined("GL_FRAGMENT_PRECISION_HIGH", "1");
    return;
  }
  if (unit_.version >= 130) define_predefined("GL_FRAGMENT_PRECISION_HIGH", "1");  // GLSL 1.30, 4.6.1
  if (unit_.version >= 150) {
    define_predefined(unit_.profile == "compatibility" ? "GL_compatibility_profile" : "GL_core_profile", "1");
  }
}

void Preprocessor::directive_extension(FileState& f, const Token& hash) {
  std::vector<Token> line = read_directive_line(f, DirectiveKind::extension, hash);
  SourceRange directive = directive_range(hash, line);
  if (line.empty() || line[0].kind != TokenKind::identifier) {
    error(code::E_DIRECTIVE, line.empty() ? directive : line[0].range, "expected an extension name after #extension");
    return;
  }
  if (line.size() < 2 || line[1].kind != TokenKind::colon) {
    error(code::E_DIRECTIVE, line.size() < 2 ? line[0].range : line[1].range, "expected ':' after the extension name");
    return;
  }
  if (line.size() < 3 || line[2].kind != TokenKind::identifier) {
    error(code::E_DIRECTIVE, line.size() < 3 ? line[1].range : line[2].range,
          "expected 'require', 'enable', 'warn' or 'disable' after ':'");
    return;
  }
  std::string_view name = line[0].text;
  std::string_view behavior = line[2].text;
  if (behavior != "require" && behavior != "enable" && behavior != "warn" && behavior != "disable") {
    error(code::E_DIRECTIVE, line[2].range,
          "unknown extension behavior '" + std::string(behavior) +
              "' (expected 'require', 'enable', 'warn' or 'disable')");
    return;
  }
  if (name == "all" && (behavior == "require" || behavior == "enable")) {
    error(code::E_DIRECTIVE, line[2].range, "'all' can only be used with 'warn' or 'disable'");
    return;
  }
  extra_tokens_warning(line, 3, "extension");
  std::uint32_t groups = extension_groups_enabled_by(name);
  if (behavior == "disable") {
    unit_.keywords.extension_groups &= ~groups;
  } else {
    unit_.keywords.extension_groups |= groups;
  }
  std::vector<std::string>& enabled = unit_.language.extensions;
  if (behavior == "disable") {
    if (name == "all") enabled.clear();
    std::erase(enabled, name);
  } else if (name != "all" && !unit_.language.extension_enabled(name)) {
    enabled.emplace_back(name);
  }
  // String literals: debugPrintfEXT's format, and the arguments of GL_EXT_spirv_intrinsics.
  strings_allowed_ = unit_.language.extension_enabled("GL_EXT_debug_printf") ||
                     unit_.language.extension_enabled("GL_EXT_spirv_intrinsics");
  const auto& supported = options_.extension_macros;
  if (options_.reject_unsupported_extensions && name != "all" && behavior != "disable" &&
      std::find(supported.begin(), supported.end(), name) == supported.end()) {
    std::string message = "extension '" + std::string(name) + "' is not supported";
    if (behavior == "require") {
      error(code::E_EXTENSION, line[0].range, std::move(message));
    } else {
      diagnostics_.report(Diagnostic::warning(line[0].range, std::move(message)).with_code(code::W_EXTENSION));
    }
  } else if (name != "all" && behavior != "disable" && !find_extension(name) && !glslang_knows_extension(name)) {
    // A typo or a name no compiler has: glslangValidator warns (refuses it with require); the
    // checker goes on, so the warning is what says the line turned nothing on.
    const std::string shown = name.size() > 64 ? std::string(name.substr(0, 60)) + "..." : std::string(name);
    Diagnostic d = Diagnostic::warning(line[0].range, "unknown extension '" + shown + "': it turns nothing on")
                       .with_code(code::W_UNKNOWN_EXTENSION);
    if (behavior == "require") d.with_hint("glslangValidator refuses a shader that requires an extension it does not know");
    diagnostics_.report(std::move(d));
  }
  unit_.extensions.push_back({std::string(name), std::string(behavior), directive});
}

void Preprocessor::directive_pragma(FileState& f, const Token& hash) {
  std::vector<Token> line = read_directive_line(f, DirectiveKind::pragma, hash);
  SourceRange directive = directive_range(hash, line);
  std::string text;
  for (const Token& t : line) {
    if (!text.empty() && t.leading_space) text += ' ';
    text += t.text;
  }
  if (text == "once") once_files_.insert(f.path);
  unit_.pragmas.push_back({std::move(text), directive});
}

void Preprocessor::directive_line(FileState& f, const Token& hash) {
  std::vector<Token> line = read_line(f);
  SourceLocation last = line.empty() ? hash.range.end : line.back().range.end;
  record_directive(DirectiveKind::line, hash, last);
  SourceRange directive = directive_range(hash, line);
  std::vector<PPToken> raw;
  for (const Token& t : line) raw.push_back(PPToken{t});
  std::vector<PPToken> expanded = expand_list(std::move(raw), kNoExpansion, 0);
  auto number = [&](std::size_t i) -> std::optional<std::uint32_t> {
    if (i >= expanded.size() || expanded[i].token.kind != TokenKind::int_literal) return std::nullopt;
    auto v = integer_literal_value(expanded[i].token.text);
    if (!v || *v > 0x7FFFFFFF) return std::nullopt;
    return static_cast<std::uint32_t>(*v);
  };
  LineDirective result;
  result.range = directive;
  auto line_number = number(0);
  if (!line_number) {
    error(code::E_DIRECTIVE, expanded.empty() ? directive : expanded[0].token.range,
          "expected a line number after #line");
    return;
  }
  result.line = *line_number;
  if (expanded.size() > 1) {
    const Token& second = expanded[1].token;
    if (second.kind == TokenKind::string_literal && second.text.size() >= 2) {
      result.file_name = std::string(second.text.substr(1, second.text.size() - 2));
    } else if (auto source_string = number(1)) {
      result.source_string = *source_string;
    } else {
      error(code::E_DIRECTIVE, second.range, "expected a source-string number or a file name after the line number");
      return;
    }
    if (expanded.size() > 2) {
      diagnostics_.report(Diagnostic::warning(expanded[2].token.range, "extra tokens at end of #line directive")
                              .with_code(code::W_EXTRA_TOKENS));
    }
  }
  // Before GLSL 3.30 (desktop), `#line N` named the directive's own line, so
  // the next line is N + 1 (glslang does the same).
  std::uint32_t next_line_number = result.line + (!unit_.es && unit_.version < 330 ? 1 : 0);
  std::uint32_t next_line = line_end_offset(last);
  std::string_view text = sources_.text(f.file);
  if (next_line < text.size() && text[next_line] == '\r') ++next_line;
  if (next_line < text.size() && text[next_line] == '\n') ++next_line;
  sources_.add_line_directive(f.file, next_line, next_line_number, result.file_name, result.source_string);
  if (result.file_name) {
    f.line_file_name = save(*result.file_name);
  } else if (result.source_string) {
    f.source_string = *result.source_string;
    f.line_file_name = {};
  }
  unit_.line_directives.push_back(std::move(result));
}

void Preprocessor::directive_error(FileState& f, const Token& hash, const Token& name) {
  SourceRange text = f.lexer.rest_of_line();
  record_directive(DirectiveKind::error, hash, text.end);
  std::string message(sources_.text(f.file).substr(text.begin.offset, text.length()));
  diagnostics_.report(Diagnostic::error(name.range, message.empty() ? "#error" : "#error: " + message)
                          .with_code(code::E_ERROR_DIRECTIVE));
}

// ------------------------------------------------------------ #include ---

void Preprocessor::directive_include(FileState& f, const Token& hash, const Token& name) {
  std::optional<Token> header = f.lexer.header_name();
  std::vector<Token> line = read_line(f);
  SourceLocation last = line.empty() ? (header ? header->range.end : name.range.end) : line.back().range.end;
  record_directive(DirectiveKind::include, hash, last);
  SourceRange directive{hash.range.begin, last};
  bool angled = header.has_value();
  if (!header && !line.empty() && line[0].kind == TokenKind::identifier) {
    // `#include NAME` where NAME expands to "file" or <file> (C 6.10.2p4).
    std::vector<PPToken> raw;
    for (const Token& t : line) raw.push_back(PPToken{t});
    std::vector<PPToken> expanded = expand_list(std::move(raw), kNoExpansion, 0);
    if (expanded.empty()) {
      error(code::E_DIRECTIVE, line[0].range, "expected \"FILENAME\" or <FILENAME> after #include");
      return;
    }
    line.clear();
    for (const PPToken& t : expanded) line.push_back(t.token);
    if (line.size() >= 2 && line.front().kind == TokenKind::less && line.back().kind == TokenKind::greater) {
      std::string spelled = "<";
      for (std::size_t i = 1; i + 1 < line.size(); ++i) {
        if (i > 1 && line[i].leading_space) spelled += ' ';
        spelled += line[i].text;
      }
      Token angled_name = line.front();
      angled_name.kind = TokenKind::string_literal;
      angled_name.text = save(spelled + ">");
      angled_name.range.end = line.back().range.end;
      header = angled_name;
      angled = true;
      line.clear();
    }
  }
  if (!header) {
    if (line.empty() || line[0].kind != TokenKind::string_literal || line[0].text.size() < 2 ||
        line[0].text.back() != '"') {
      error(code::E_DIRECTIVE, line.empty() ? name.range : line[0].range,
            "expected \"FILENAME\" or <FILENAME> after #include");
      return;
    }
    header = line[0];
    line.erase(line.begin());
  }
  extra_tokens_warning(line, 0, "include");
  std::string requested(header->text.substr(1, header->text.size() - 2));
  if (requested.empty()) {
    error(code::E_INCLUDE, header->range, "empty file name in #include");
    return;
  }
  if (static_cast<int>(files_.size()) > options_.max_include_depth) {
    error(code::E_LIMIT, directive,
          "#include nested too deeply (limit " + std::to_string(options_.max_include_depth) + ")");
    aborted_ = true;
    return;
  }
  namespace fs = std::filesystem;
  std::vector<std::string> candidates;
  if (fs::path(requested).is_absolute()) {
    candidates.push_back(requested);
  } else {
    if (!angled) candidates.push_back((fs::path(f.path).parent_path() / requested).lexically_normal().string());
    for (const std::string& dir : options_.include_paths) {
      candidates.push_back((fs::path(dir) / requested).lexically_normal().string());
    }
  }
  std::string resolved;
  std::optional<std::string> contents;
  for (const std::string& candidate : candidates) {
    if (loaded_files_.count(candidate)) {
      resolved = candidate;
      break;
    }
    contents = options_.read_file ? options_.read_file(candidate) : read_from_disk(candidate);
    if (contents) {
      resolved = candidate;
      break;
    }
  }
  if (resolved.empty()) {
    Diagnostic d = Diagnostic::error(header->range, "'" + requested + "' file not found").with_code(code::E_INCLUDE);
    if (!candidates.empty()) {
      std::string searched;
      for (const std::string& c : candidates) searched += (searched.empty() ? "" : ", ") + c;
      d.with_hint("searched " + searched);
    }
    diagnostics_.report(std::move(d));
    return;
  }
  if (once_files_.count(resolved)) return;
  for (const auto& open : files_) {
    if (open->path == resolved && !open->is_command_line) {
      std::string chain;
      for (const auto& g : files_) {
        if (!g->is_command_line) chain += g->path + " -> ";
      }
      error(code::E_INCLUDE, header->range, "#include cycle: " + chain + resolved);
      return;
    }
  }
  FileId id;
  if (auto it = loaded_files_.find(resolved); it != loaded_files_.end()) {
    id = sources_.add_inclusion(it->second, directive);
  } else {
    if (contents->size() > options_.max_source_bytes) {
      error(code::E_INCLUDE, header->range,
            "'" + requested + "' is too large (" + std::to_string(contents->size()) + " bytes; limit " +
                std::to_string(options_.max_source_bytes) + ")");
      return;
    }
    id = sources_.add_file(resolved, std::move(*contents));
    sources_.set_included_from(id, directive);
    loaded_files_.emplace(resolved, id);
    if (refuse_non_text(id)) return;
  }
  if (unit_.includes.size() >= options_.max_include_count) {
    error(code::E_LIMIT, directive,
          "more than " + std::to_string(options_.max_include_count) + " #include directives processed");
    aborted_ = true;
    return;
  }
  unit_.includes.push_back({id, resolved, directive});
  auto state = std::make_unique<FileState>(sources_, id, diagnostics_, resolved);
  state->conditional_base = conditionals_.size();
  files_.push_back(std::move(state));
}

}  // namespace safegi::detail
