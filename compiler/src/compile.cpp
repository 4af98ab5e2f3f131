#include "safegi/compiler/compile.hpp"

#include <pthread.h>

#include <algorithm>
#include <exception>

#include <safegi/diagnostics/codes.hpp>
#include <safegi/diagnostics/file.hpp>
#include <safegi/diagnostics/printable.hpp>
#include <safegi/diagnostics/render.hpp>
#include <safegi/elider/elider.hpp>
#include <safegi/lexer/preprocessor.hpp>
#include <safegi/parser/parser.hpp>

namespace safegi {
namespace {

// Pipeline order (stages.def), for the cross-stage check between neighbours.
int pipeline_index(Stage s) {
  const std::vector<StageInfo>& table = stage_table();
  for (std::size_t i = 0; i < table.size(); ++i)
    if (table[i].stage == s) return static_cast<int>(i);
  return static_cast<int>(table.size());
}

struct StageWork {
  const ShaderSource* source = nullptr;
  Stage stage = Stage::unknown;
  FileId file = kNoFile;
  PreprocessedUnit preprocessed;
  ParseResult parsed;
  std::optional<CheckResult> checked;
  bool ok = false;
};

// Diagnostics are text for terminals and JSON: bytes that are not UTF-8 (a
// stray byte of the source quoted in a message, a file name) become `\xNN`.
std::string valid_utf8(std::string_view text) { return escape_invalid_utf8(text); }

void make_printable(Diagnostic& d) {
  d.message = valid_utf8(d.message);
  d.hint = valid_utf8(d.hint);
  for (Diagnostic& note : d.notes) make_printable(note);
}

// `#version 300 es`, `#version 450 core`, `#version 100`.
std::string version_line(const PreprocessedUnit& unit) {
  std::string line = "#version " + std::to_string(unit.version);
  if (!unit.profile.empty()) line += " " + unit.profile;
  return line;
}

// The emitted GLSL states the version it was checked as, so that a driver
// or glslang reads it as the checker did: a shader without #version gets
// the default's line (then `#line` restores the numbering: the next line is
// N from 3.30 and ES on, N + 1 before), and --glsl-version rewrites the
// line a shader has, in place.
std::string with_checked_version(std::string glsl, const PreprocessedUnit& unit, bool overridden) {
  if (!unit.version_given) {
    const bool next_line_is_n = unit.es || unit.version == 100 || unit.version >= 330;
    return version_line(unit) + "\n#line " + (next_line_is_n ? "1" : "0") + "\n" + glsl;
  }
  if (!overridden) return glsl;
  // Erasure keeps lines and nothing can be inserted before #version, so the
  // directive is on its own source line in the output.
  std::size_t begin = 0;
  for (std::uint32_t line = 1; line < unit.version_range.begin.line && begin != std::string::npos; ++line) {
    begin = glsl.find('\n', begin);
    if (begin != std::string::npos) ++begin;
  }
  if (begin == std::string::npos) return glsl;
  const std::size_t end = std::min(glsl.find('\n', begin), glsl.size());
  return glsl.substr(0, begin) + version_line(unit) + glsl.substr(end);
}

}  // namespace

std::optional<GlslVersion> parse_glsl_version(std::string_view text) {
  static constexpr std::pair<std::string_view, GlslVersion> kVersions[] = {
      {"100", {100, true}},   {"110", {110, false}},  {"120", {120, false}},  {"130", {130, false}},
      {"140", {140, false}},  {"150", {150, false}},  {"300es", {300, true}}, {"310es", {310, true}},
      {"320es", {320, true}}, {"330", {330, false}},  {"400", {400, false}},  {"410", {410, false}},
      {"420", {420, false}},  {"430", {430, false}},  {"440", {440, false}},  {"450", {450, false}},
      {"460", {460, false}}};
  for (const auto& [name, version] : kVersions)
    if (text == name) return version;
  return std::nullopt;
}

std::string to_string(const GlslVersion& version) {
  return std::to_string(version.number) + (version.es && version.number != 100 ? "es" : "");
}

std::optional<Stage> stage_from_name(std::string_view name) {
  // Its extension, its long name, or its id in stages.def (the symbol table's name: "tess_control").
  for (const StageInfo& s : stage_table())
    if (name == s.extension || name == s.long_name || name == gl::to_string(*to_table_stage(s.stage))) return s.stage;
  return std::nullopt;
}

std::optional<Stage> stage_from_path(std::string_view path) {
  std::string_view name = path.substr(std::min(path.size(), path.find_last_of("/\\") + 1));
  if (name.size() > 4 && name.substr(name.size() - 4) == ".sgl") name.remove_suffix(4);  // light.vert.sgl
  const std::size_t dot = name.find_last_of('.');
  if (dot == std::string_view::npos) return std::nullopt;
  std::string_view ext = name.substr(dot + 1);
  for (const StageInfo& s : stage_table())
    if (ext == s.extension) return s.stage;
  return std::nullopt;
}

std::string_view stage_extension(Stage stage) {
  const StageInfo* info = stage_info(stage);
  return info ? info->extension : "";
}

std::string stage_extension_list(std::string_view separator, std::string_view prefix) {
  std::string list;
  for (const StageInfo& s : stage_table()) list += (list.empty() ? "" : std::string(separator)) + std::string(prefix) + s.extension;
  return list;
}

std::optional<gl::Stage> to_table_stage(Stage stage) {
  switch (stage) {
#define SAFEGI_STAGE(id, ...) \
  case Stage::id: return gl::Stage::id;
#include <safegi/symbol_table/stages.def>
    case Stage::unknown: break;
  }
  return std::nullopt;
}

std::string CompileResult::diagnostics_text(bool color) const {
  if (!sources) return {};
  TextStyle style;
  style.color = color;
  return render_text(diagnostics, *sources, style);
}

std::string CompileResult::diagnostics_json() const {
  if (!sources) return "{\"diagnostics\": []}";
  return render_json(diagnostics, *sources);
}

std::size_t CompileResult::error_count() const {
  return static_cast<std::size_t>(std::count_if(diagnostics.begin(), diagnostics.end(),
                                                [](const Diagnostic& d) { return d.severity == Severity::error; }));
}

std::size_t CompileResult::warning_count() const {
  return static_cast<std::size_t>(std::count_if(diagnostics.begin(), diagnostics.end(),
                                                [](const Diagnostic& d) { return d.severity == Severity::warning; }));
}

namespace {

void add_dependency(CompileResult& result, const std::string& path) {
  if (path.rfind(kBuiltinIncludeDir, 0) == 0 || path == "<stdin>") return;  // served from memory
  if (std::find(result.dependencies.begin(), result.dependencies.end(), path) == result.dependencies.end())
    result.dependencies.push_back(path);
}

// The front end, the checker and the elider recurse over the syntax tree. The
// parser bounds its depth (256 nesting levels, chains of at most 2048 binary
// or postfix operators); this stack holds
// the deepest tree it accepts even under AddressSanitizer, whatever stack the
// caller's thread has (a library call may come from a small worker thread).
// Only touched pages cost memory.
constexpr std::size_t kCompileStackBytes = std::size_t{512} << 20;

template <class Work>
void run_with_large_stack(Work& work) {
  struct Task {
    Work* work;
    std::exception_ptr error;
  } task{&work, nullptr};
  auto entry = [](void* argument) -> void* {
    auto* t = static_cast<Task*>(argument);
    try {
      (*t->work)();
    } catch (...) {
      t->error = std::current_exception();
    }
    return nullptr;
  };
  pthread_attr_t attributes;
  pthread_t thread;
  bool started = false;
  if (pthread_attr_init(&attributes) == 0) {  // only initialised attributes may be destroyed
    started = pthread_attr_setstacksize(&attributes, kCompileStackBytes) == 0 &&
              pthread_create(&thread, &attributes, entry, &task) == 0;
    pthread_attr_destroy(&attributes);
  }
  if (!started) return work();  // no thread to be had: the caller's own stack
  pthread_join(thread, nullptr);
  if (task.error) std::rethrow_exception(task.error);
}

CompileResult compile_here(const std::vector<ShaderSource>& sources, const CompileOptions& options) {
  auto manager = std::make_shared<SourceManager>();
  DiagnosticEngine diags(options.diagnostics);
  CompileResult result;

  const PreprocessorOptions pp = preprocessor_options(options);

  std::vector<StageWork> work(sources.size());
  for (std::size_t i = 0; i < sources.size(); ++i) {
    StageWork& w = work[i];
    w.source = &sources[i];
    w.file = manager->add_file(valid_utf8(sources[i].path), sources[i].text);
    std::optional<Stage> stage = sources[i].stage ? sources[i].stage : stage_from_path(sources[i].path);
    if (!stage || *stage == Stage::unknown) {
      diags.report(Diagnostic::error(manager->range_of(w.file, 0, 0),
                                     "cannot tell the shader stage of '" + sources[i].path + "' from its name")
                       .with_code(code::E_PROGRAM)
                       .with_hint("name it *.vert, *.frag, … (or *.sgl.frag), or give the stage with -S"));
      continue;
    }
    // A ray-tracing pipeline has as many hit, miss and callable shaders as it likes.
    const bool one_per_program = stage_info(*stage)->family != StageFamily::ray_tracing;
    for (std::size_t j = 0; j < i && one_per_program; ++j)
      if (work[j].stage == *stage) {
        diags.report(Diagnostic::error(manager->range_of(w.file, 0, 0),
                                       "a program has at most one " + std::string(stage_extension(*stage)) + " stage")
                         .with_code(code::E_PROGRAM)
                         .with_note(Diagnostic::note(manager->range_of(work[j].file, 0, 0), "the other one is here")));
      }
    w.stage = *stage;
    if (diags.limit_reached()) break;
    const std::size_t errors_before = diags.error_count();
    w.preprocessed = preprocess(*manager, w.file, pp, diags);
    // The syntax the #version and extensions allow; after a preprocessor error
    // (a misplaced #version, say) the level is a guess, and its gates would
    // only add cascades.
    ParseOptions parse_options;
    if (diags.error_count() == errors_before) parse_options.language = w.preprocessed.language;
    w.parsed = parse(w.preprocessed.tokens, diags, parse_options);
    add_dependency(result, sources[i].path);
    for (const IncludedFile& inc : w.preprocessed.includes) add_dependency(result, inc.path);
    // A tree with syntax errors is partial: checking it would only add cascades.
    if (diags.error_count() != errors_before || diags.limit_reached()) continue;
    CheckOptions check_options;
    check_options.stage = w.stage;
    check_options.strict = options.strict;
    check_options.language = parse_options.language;  // unset after a preprocessor error, as for the parser
    check_options.version_range = w.preprocessed.version_range;
    check_options.tokens = &w.preprocessed.tokens;
    check_options.sources = manager.get();
    check_options.record_symbols = options.keep_analysis;
    w.checked = check(*w.parsed.unit, check_options, diags);
    w.ok = diags.error_count() == errors_before;
  }

  // Cross-stage check between neighbouring stages of the pipeline.
  std::vector<StageWork*> ordered;
  for (StageWork& w : work)
    if (w.checked) ordered.push_back(&w);
  std::stable_sort(ordered.begin(), ordered.end(),
                   [](const StageWork* a, const StageWork* b) { return pipeline_index(a->stage) < pipeline_index(b->stage); });
  for (std::size_t i = 1; i < ordered.size(); ++i)
    if (stage_info(ordered[i - 1]->stage)->family == StageFamily::graphics &&
        stage_info(ordered[i]->stage)->family == StageFamily::graphics)
      check_interface_match(*ordered[i - 1]->checked, *ordered[i]->checked, diags);

  // Ray tracing: what the ray generation shader traces reaches the hit and miss shaders.
  for (const StageWork* tracer : ordered)
    if (tracer->stage == Stage::ray_generation)
      for (const StageWork* receiver : ordered)
        if (receiver->stage == Stage::closest_hit || receiver->stage == Stage::any_hit || receiver->stage == Stage::miss)
          check_payload_match(*tracer->checked, *receiver->checked, diags);

  gl::SymbolTable& table = result.symbols;
  table.mode = sources.size() > 1 ? gl::TableMode::program : gl::TableMode::shader;
  table.compiler = std::string(kCompilerName) + " " + std::string(kCompilerVersion);
  std::string stage_hashes;
  for (StageWork& w : work) {
    StageOutput out;
    out.stage = w.stage;
    out.path = w.source->path;
    if (w.ok && !diags.has_errors()) {
      ElideInput input{*manager, w.file, w.preprocessed, *w.parsed.unit, *w.checked, options.defines, options.undefines,
                       options.emit};
      ElideResult elided = elide(input, diags);
      if (options.emit) {
        out.glsl = with_checked_version(std::move(elided.glsl), w.preprocessed, options.override_version.has_value());
        if (std::optional<gl::Stage> table_stage = to_table_stage(w.stage)) {
          table.stages.push_back(stage_symbols(input, *table_stage, w.source->path, elided.source_files));
          stage_hashes += table.stages.back().source_hash;
        }
        add_declarations(table, input);
      }
    }
    if (options.keep_analysis && w.checked) {
      auto analysis = std::make_shared<StageAnalysis>();
      analysis->file = w.file;
      analysis->preprocessed = std::move(w.preprocessed);
      analysis->parsed = std::move(w.parsed);
      analysis->checked = std::move(*w.checked);
      out.analysis = std::move(analysis);
    }
    result.stages.push_back(std::move(out));
  }
  table.source_hash = source_hash(stage_hashes);
  trim_vocabulary(table);
  result.success = !diags.has_errors();
  if (!result.success) {
    for (StageOutput& s : result.stages) s.glsl.clear();
    table.stages.clear();
  }
  result.diagnostics = diags.diagnostics();
  for (Diagnostic& d : result.diagnostics) make_printable(d);
  result.sources = std::move(manager);
  return result;
}

}  // namespace

std::optional<std::string> read_file_from_disk(const std::string& path) { return read_file(path); }

PreprocessorOptions preprocessor_options(const CompileOptions& options) {
  PreprocessorOptions pp;
  pp.include_paths = options.include_paths;
  pp.include_paths.emplace_back(kBuiltinIncludeDir);
  pp.defines = options.defines;
  pp.undefines = options.undefines;
  pp.default_version = options.default_version.number;
  pp.default_es = options.default_version.es;
  pp.vulkan = options.vulkan;
  if (options.override_version) {
    pp.override_version = options.override_version->number;
    pp.override_es = options.override_version->es;
  }
  pp.read_file = [read = options.read_file](const std::string& path) -> std::optional<std::string> {
    if (path == kBuiltinPreludePath) return std::string(prelude_text());
    if (path.rfind(kBuiltinIncludeDir, 0) == 0) return std::nullopt;
    return read ? read(path) : read_file_from_disk(path);
  };
  return pp;
}

CompileResult compile(const std::vector<ShaderSource>& sources, const CompileOptions& options) {
  CompileResult result;
  auto work = [&] { result = compile_here(sources, options); };
  run_with_large_stack(work);
  return result;
}

}  // namespace safegi
