#pragma once
// The GLSL preprocessor: #version, #extension, #pragma, #line, #error,
// object- and function-like macros with ##, conditionals with full constant
// expressions, #include (GL_GOOGLE_include_directive semantics). Every output
// token keeps its spelling range and the macro expansion that produced it.
//
// No global state: preprocess() may run on several threads at once as long
// as each call has its own SourceManager and DiagnosticEngine.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <safegi/diagnostics/diagnostic.hpp>
#include <safegi/diagnostics/source_manager.hpp>
#include <safegi/lexer/extensions.hpp>
#include <safegi/lexer/token.hpp>

namespace safegi {

struct PreprocessorOptions {
  std::vector<std::string> include_paths;                       // -I, searched in order
  std::vector<std::pair<std::string, std::string>> defines;     // -D NAME=value (value may be empty)
  std::vector<std::string> undefines;                           // -U NAME
  // Extensions the target supports: each is predefined as a macro with value
  // 1, as drivers do (`#ifdef GL_ARB_gpu_shader5`). Default: the extensions
  // whose syntax the front end parses (known_extensions(), docs/preprocessor.md).
  std::vector<std::string> extension_macros = default_extension_macros();
  // When set, `#extension X : require` of an extension not in
  // extension_macros is an error (enable and warn: a warning), as a driver
  // reports it. Off by default: the type checker, not the preprocessor,
  // knows which built-ins an unknown extension would have added.
  bool reject_unsupported_extensions = false;
  // The language of a shader without #version: 1.10 desktop by default (the
  // GLSL rule); safeglslc passes glslangValidator's ES 1.00 unless given -d.
  int default_version = 110;
  bool default_es = false;
  // When non-zero, the language whatever the #version line says (the line is
  // still checked): safeglslc --glsl-version, glslangValidator's option.
  int override_version = 0;
  bool override_es = false;
  // Vulkan GLSL (GL_KHR_vulkan_glsl), as glslangValidator -V: when non-zero,
  // the value of the predefined `VULKAN` macro (100), the Vulkan types are
  // keywords and LanguageLevel::extensions lists GL_KHR_vulkan_glsl, which
  // turns on the checker's Vulkan rules (push constants, set, std430 push-constant
  // blocks). 0: OpenGL GLSL.
  int vulkan = 0;
  // Reads an include candidate; nullopt when it does not exist. Default: the
  // file system. Tests and embedders (an in-memory prelude) replace it.
  std::function<std::optional<std::string>(const std::string& path)> read_file;

  // Limits: exceeding one is a diagnostic, never a crash or a hang.
  int max_include_depth = 64;
  int max_expansion_depth = 256;           // nested macro expansions / #if nesting in expressions
  std::size_t max_output_tokens = 2u << 20;
  std::size_t max_include_count = 10000;   // #include directives processed in all
  std::size_t max_source_bytes = 64u << 20;  // per file
  int max_conditional_depth = 1024;        // nested #if
};

struct ExtensionDirective {
  std::string name;      // "GL_ARB_gpu_shader5" or "all"
  std::string behavior;  // require, enable, warn, disable
  SourceRange range;     // the whole directive line
};

struct PragmaDirective {
  std::string text;  // the tokens after #pragma; one space wherever the source had white space
  SourceRange range;
};

struct LineDirective {
  std::uint32_t line = 0;
  std::optional<std::uint32_t> source_string;
  std::optional<std::string> file_name;  // GL_GOOGLE_cpp_style_line_directive: #line N "name"
  SourceRange range;
};

enum class DirectiveKind : std::uint8_t {
  null_directive, version, extension, pragma, line, error, define, undef, if_, ifdef, ifndef, elif, else_,
  endif, include, unknown
};

// A directive line as it appears in the source: from '#' to the end of its
// last (continued) line, newline excluded. The elider blanks or copies these.
struct DirectiveLine {
  DirectiveKind kind = DirectiveKind::unknown;
  SourceRange range;
};

struct IncludedFile {
  FileId file = kNoFile;    // this inclusion's FileId
  std::string path;         // the resolved path
  SourceRange directive;    // the #include line that pulled it in
};

struct PreprocessedUnit {
  std::vector<Token> tokens;  // ends with an eof token
  int version = 110;          // #version; PreprocessorOptions' default when absent, its override when set
  std::string profile;        // "", "core", "compatibility", "es"
  bool es = false;
  bool version_given = false;
  SourceRange version_range;  // the #version line, if any
  KeywordContext keywords;    // the context the words were classified in (after all #extension)
  LanguageLevel language;     // #version and enabled extensions, for the parser's feature gates
  std::vector<ExtensionDirective> extensions;
  std::vector<PragmaDirective> pragmas;
  std::vector<LineDirective> line_directives;
  std::vector<DirectiveLine> directives;     // every directive in every file, in order
  std::vector<SourceRange> skipped_ranges;   // lines of groups an #if removed (directives excluded)
  std::vector<IncludedFile> includes;
};

PreprocessedUnit preprocess(SourceManager& sources, FileId main_file, const PreprocessorOptions& options,
                            DiagnosticEngine& diagnostics);

}  // namespace safegi
