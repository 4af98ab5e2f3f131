#pragma once
// safegi::compile: annotated GLSL in; plain GLSL per stage, one symbol table
// and the diagnostics out. The whole pipeline (preprocess, parse, check,
// elide) runs on values owned by the call: no global state, so several
// threads may compile at once. The standard prelude is built in
// (`#include <safegi/prelude.sgl>` needs no include path).
//
//   safegi::CompileResult r = safegi::compile({{"shade.sgl.frag", text}});
//   if (!r.success) std::cerr << r.diagnostics_text();

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <safegi/diagnostics/diagnostic.hpp>
#include <safegi/diagnostics/source_manager.hpp>
#include <safegi/lexer/preprocessor.hpp>
#include <safegi/parser/parser.hpp>
#include <safegi/symbol_table/symbol_table.hpp>
#include <safegi/typechecker/checker.hpp>

namespace safegi {

inline constexpr std::string_view kCompilerName = "safeglslc";
inline constexpr std::string_view kCompilerVersion = "0.1.0";

struct ShaderSource {
  std::string path;                 // as the user names it; used in diagnostics and the symbol table
  std::string text;
  std::optional<Stage> stage = {};  // default: from the file extension (stage_from_path)
};

// A GLSL language version: 100 and 300/310/320 are ES ("300es"), the others desktop.
struct GlslVersion {
  int number = 100;
  bool es = true;
  friend bool operator==(const GlslVersion&, const GlslVersion&) = default;
};
// glslangValidator's --glsl-version spellings: 100 110 120 130 140 150 300es
// 310es 320es 330 400 410 420 430 440 450 460.
std::optional<GlslVersion> parse_glsl_version(std::string_view text);
std::string to_string(const GlslVersion& version);  // "300es", "450"

struct CompileOptions {
  std::vector<std::string> include_paths;                    // -I, searched in order, before the built-in prelude
  std::vector<std::pair<std::string, std::string>> defines;  // -D NAME[=value]
  std::vector<std::string> undefines;                        // -U NAME
  bool strict = false;                                       // --strict: warn on unannotated interface variables
  DiagnosticOptions diagnostics;                             // -Werror, -w, error limit
  // The language of a shader without #version. glslangValidator's default, ES
  // 1.00; `-d` makes it desktop 1.10 (what a desktop driver assumes).
  GlslVersion default_version{100, true};
  // --glsl-version: check every shader as this version whatever its #version
  // says. Either way the emitted GLSL states the version it was checked as.
  std::optional<GlslVersion> override_version;
  // Vulkan GLSL (GL_KHR_vulkan_glsl): non-zero, the value of `VULKAN` (100).
  // safeglslc sets it for -V / --target-env vulkan*; 0: OpenGL rules.
  int vulkan = 0;
  // Reads `#include`d files; default: the file system. The prelude is always
  // served from memory.
  std::function<std::optional<std::string>(const std::string& path)> read_file;
  // Keep each checked stage's tokens, syntax tree and checker result, with
  // the checker's symbols recorded (StageOutput::analysis): what an editor
  // asks about (lsp/). Off by default.
  bool keep_analysis = false;
  // Off: check only. Every diagnostic is still found (the elider's too), but
  // no GLSL is rendered and no symbol table built, which safeglslc without
  // -o, --symbols or SPIR-V output does not need.
  bool emit = true;
};

// One stage's front-end products, kept when CompileOptions::keep_analysis is
// set. Locations refer to CompileResult::sources.
struct StageAnalysis {
  FileId file = kNoFile;        // the stage's main file
  PreprocessedUnit preprocessed;
  ParseResult parsed;
  CheckResult checked;          // with CheckResult::symbols
};

struct StageOutput {
  Stage stage = Stage::unknown;
  std::string path;
  std::string glsl;  // empty when the stage had errors
  // With CompileOptions::keep_analysis, for a stage that parsed (and so was
  // checked); null otherwise.
  std::shared_ptr<const StageAnalysis> analysis;
};

struct CompileResult {
  bool success = false;               // no errors: every stage has its GLSL and the table is complete
  std::vector<StageOutput> stages;    // in the order of the sources
  gl::SymbolTable symbols;            // one table: "shader" mode for one source, "program" for several
  std::vector<Diagnostic> diagnostics;
  std::shared_ptr<const SourceManager> sources;  // what the diagnostics' locations refer to
  // Every file the compilation read: the sources' paths, then each file they
  // `#include`d, in inclusion order, each once (the built-in prelude, served from
  // memory, is not one). What a make-style depfile lists (safeglslc -MD).
  std::vector<std::string> dependencies;

  std::string symbols_json() const { return gl::to_json(symbols); }
  std::string diagnostics_text(bool color = false) const;
  std::string diagnostics_json() const;
  std::size_t error_count() const;
  std::size_t warning_count() const;
};

// One shader, or several stages of one program (at most one per stage, except
// ray-tracing stages, then checked against each other: each stage's outputs
// against the next stage's inputs, each hit and miss shader's payload against
// the ray generation shader's).
CompileResult compile(const std::vector<ShaderSource>& sources, const CompileOptions& options = {});

// The extensions of stages.def (`.vert` … `.comp`, `.rgen .rint .rahit
// .rchit .rmiss .rcall .mesh .task`), also after the annotated-source suffix
// `.sgl` (`light.sgl.frag`) and as `.vert.sgl`; nothing otherwise.
std::optional<Stage> stage_from_path(std::string_view path);
// `vert`/`vertex`, `frag`/`fragment`, `rgen`/`raygen`, … (glslangValidator's -S names).
std::optional<Stage> stage_from_name(std::string_view name);
std::string_view stage_extension(Stage stage);  // "vert", ...
// Every stage's extension in pipeline order, each after `prefix`, joined by
// `separator`: what messages list (".vert .tesc … .rcall").
std::string stage_extension_list(std::string_view separator, std::string_view prefix = "");
std::optional<gl::Stage> to_table_stage(Stage stage);

// The built-in prelude's text and the virtual include directory that serves it.
std::string_view prelude_text();
inline constexpr std::string_view kBuiltinIncludeDir = "<builtin>";
inline constexpr std::string_view kBuiltinPreludePath = "<builtin>/safegi/prelude.sgl";  // its path in diagnostics

// compile()'s default reader: the file's bytes, or nothing when it cannot be read.
std::optional<std::string> read_file_from_disk(const std::string& path);

// The preprocessor options compile() runs with: `options`' include paths,
// then the built-in directory serving the prelude; its reader, else the disk.
// For tools that preprocess on their own (lsp/ completion).
PreprocessorOptions preprocessor_options(const CompileOptions& options);

}  // namespace safegi
