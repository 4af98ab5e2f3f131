#include "safegi/compiler/cli.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include <CLI/CLI.hpp>
#include <safegi/diagnostics/codes.hpp>
#include <safegi/diagnostics/command_line.hpp>
#include <safegi/diagnostics/file.hpp>

#include "safegi/compiler/compile.hpp"
#include "safegi/compiler/spirv.hpp"

namespace safegi {
namespace {

constexpr int kExitDiagnostics = kExitInputError;

// A version number as glslangValidator takes them (-V100): digits, few enough for an int.
bool all_digits(std::string_view text) {
  return !text.empty() && text.size() <= 6 && text.find_first_not_of("0123456789") == std::string_view::npos;
}

// glslangValidator/clang spellings CLI11 cannot declare: -Werror, -ferror-limit=N, -MD, -MF,
// -V[ver] and -G[ver] (--client vulkan<ver> / opengl<ver>).
std::vector<std::string> normalise(const std::vector<std::string>& args) {
  std::vector<std::string> out;
  for (const std::string& a : args) {
    if (a.size() >= 2 && (a[1] == 'V' || a[1] == 'G') && a[0] == '-' && (a.size() == 2 || all_digits(a.substr(2))))
      out.push_back(std::string("--client=") + (a[1] == 'V' ? "vulkan" : "opengl") + (a.size() == 2 ? "100" : a.substr(2)));
    else if (a == "-Werror") out.emplace_back("--Werror");
    else if (a == "-MD") out.emplace_back("--MD");
    else if (a == "-MF") out.emplace_back("--MF");
    else if (a.rfind("-ferror-limit=", 0) == 0) out.push_back("--error-limit=" + a.substr(14));
    else if (a == "-ferror-limit") out.emplace_back("--error-limit");
    else out.push_back(a);
  }
  return out;
}

std::pair<std::string, std::string> split_define(const std::string& text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos) return {text, "1"};
  return {text.substr(0, eq), text.substr(eq + 1)};
}

// --client vulkan100 / opengl100 (glslangValidator's spelling of -V100 / -G100).
bool apply_client(const std::string& text, SpirvOptions& options) {
  for (const auto& [prefix, client] : {std::pair{"vulkan", SpirvClient::vulkan}, std::pair{"opengl", SpirvClient::opengl}}) {
    const std::string_view name(prefix);
    if (text.rfind(name, 0) == 0 && all_digits(std::string_view(text).substr(name.size()))) {
      options.client = client;
      options.client_version = std::stoi(text.substr(name.size()));
      return true;
    }
  }
  return false;
}

// The driver's own errors end as its diagnostics do, with their code (codes.def):
// "safeglslc: error: cannot read 'x.frag' [E-FILE]". Returns kExitUsage.
template <typename... Parts>
int driver_error(CliStreams& io, std::string_view code, const Parts&... what) {
  io.err << "safeglslc: error: ";
  (io.err << ... << what);
  io.err << " [" << code << "]\n";
  return kExitUsage;
}

bool write_output(const std::string& path, const std::string& text, CliStreams& io) {
  if (path == "-") {
    io.out << text;
    return static_cast<bool>(io.out);
  }
  std::ofstream file(path, std::ios::binary);
  file << text;
  file.close();
  if (!file) {
    driver_error(io, code::E_FILE, "cannot write '", path, "'");
    return false;
  }
  return true;
}

// A make-style depfile: `target: dep dep ...`, spaces in paths escaped.
std::string depfile_text(const std::string& target, const std::vector<std::string>& dependencies) {
  auto escape = [](const std::string& path) {
    std::string out;
    for (char c : path) {
      if (c == ' ' || c == '#') out += '\\';
      if (c == '$') out += '$';
      out += c;
    }
    return out;
  };
  std::string text = escape(target) + ":";
  for (const std::string& d : dependencies) text += " \\\n  " + escape(d);
  return text + "\n";
}

// The lines glslang's log marks as errors, once mapped ("file:12: error: ...").
std::size_t count_errors(const std::string& log) {
  std::size_t count = 0;
  for (std::size_t at = log.find(": error: "); at != std::string::npos; at = log.find(": error: ", at + 1)) ++count;
  return count;
}

bool names_spirv(const std::string& path) { return path.size() > 4 && path.compare(path.size() - 4, 4, ".spv") == 0; }

// --target-env sets the environment only; the outputs say the form: SPIR-V when each is named
// .spv, or when none is named (glslangValidator's vert.spv, ...); plain GLSL of that environment
// otherwise (a Vulkan build whose glslc compiles the checked text). Empty: a mix of both.
std::optional<bool> target_env_writes_spirv(const std::vector<std::string>& outputs) {
  const auto spv = static_cast<std::size_t>(std::count_if(outputs.begin(), outputs.end(), names_spirv));
  if (spv != 0 && spv != outputs.size()) return std::nullopt;
  return outputs.empty() || spv == outputs.size();
}

}  // namespace

bool wants_spirv(const std::vector<std::string>& raw_args) {
  static const std::string_view kSpirvOnly[] = {"--client", "--aml", "--auto-map-locations", "--amb", "--auto-map-bindings",
                                                "-R", "-g"};
  const std::vector<std::string> args = normalise(raw_args);
  bool target_env = false;
  std::vector<std::string> outputs;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string_view flag = std::string_view(args[i]).substr(0, args[i].find('='));
    for (std::string_view name : kSpirvOnly)
      if (flag == name) return true;
    target_env = target_env || flag == "--target-env";
    if (args[i] == "-o" && i + 1 < args.size()) outputs.push_back(args[i + 1]);
  }
  return target_env && target_env_writes_spirv(outputs).value_or(true);
}

int run_safeglslc(const std::vector<std::string>& raw_args, CliStreams& io, SpirvBackend spirv_backend) {
  CLI::App app{"safeglslc: checks the dimensions and spaces of annotated GLSL and writes plain GLSL plus a "
               "JSON symbol table (docs/safeglslc.md)",
               "safeglslc"};
  std::vector<std::string> files, outputs, include_paths, defines, undefines;
  std::string stage_name, symbols_path, depfile_path, diagnostics_format = "text", color = "auto";
  std::string glsl_version, client;
  std::vector<std::string> target_envs;
  bool werror = false, no_warnings = false, strict = false, write_depfile = false, desktop_default = false;
  bool auto_map_locations = false, auto_map_bindings = false, relaxed = false, debug_info = false;
  std::size_t error_limit = 20;  // clang's default: a file of garbage is not thousands of lines
  // `--explain CODE`, as rustc's: what a diagnostic code means; nothing is compiled, so no file is needed.
  std::string explain_code;
  app.add_option("--explain", explain_code, "print what a diagnostic code (E-DIMENSION-MISMATCH) means, and exit");
  if (raw_args.size() == 2 && raw_args[0] == "--explain") {
    const std::string text = explain_diagnostic_code(raw_args[1]);
    if (text.empty()) {
      return driver_error(io, code::E_COMMAND_LINE, "'", raw_args[1], "' is no diagnostic code (docs/typechecker.md lists them)");
    }
    io.out << text;
    return 0;
  }
  app.add_option("files", files, "annotated shaders (.sgl.vert, .frag, …); '-' reads stdin (needs -S)")->required();
  const std::string stage_words = stage_extension_list(" ");
  app.add_option("-S,--stage", stage_name, "stage of every input: " + stage_words);
  // Each occurrence of a repeatable flag takes one value (`-D A file.frag`).
  app.add_option("-o", outputs, "write the plain GLSL of each input, in order ('-' for stdout)")->allow_extra_args(false);
  app.add_option("--symbols", symbols_path, "write the JSON symbol table ('-' for stdout)");
  app.add_option("-I", include_paths, "add an #include search directory")->allow_extra_args(false);
  app.add_option("-D", defines, "define a macro: NAME or NAME=value")->allow_extra_args(false);
  app.add_option("-U", undefines, "undefine a macro")->allow_extra_args(false);
  app.add_flag("--MD", write_depfile, "write a make-style depfile of the inputs and every file they #include (also -MD)");
  app.add_option("--MF", depfile_path, "the depfile's path, default: the first -o output (or --symbols) plus '.d' (also -MF)")
      ->allow_extra_args(false);
  app.add_flag("-d", desktop_default, "a shader without #version is desktop GLSL 1.10 (default: ES 1.00, as glslangValidator)");
  app.add_option("--glsl-version", glsl_version,
                 "check as this version whatever #version says: 100 110 120 130 140 150 300es 310es 320es 330 400 "
                 "410 420 430 440 450 460");
  app.add_option("--client", client,
                 "write SPIR-V: vulkan100 (same as -V) or opengl100 (same as -G); -o then names the .spv files "
                 "(default <stage>.spv)");
  app.add_option("--target-env", target_envs,
                 "SPIR-V environment: vulkan1.0 vulkan1.1 vulkan1.2 vulkan1.3 (imply -V), opengl (implies -G), "
                 "spirv1.0 ... spirv1.6")
      ->allow_extra_args(false);
  app.add_flag("--aml,--auto-map-locations", auto_map_locations,
               "SPIR-V: give in/out and uniform variables without layout(location) one (default with -G)");
  app.add_flag("--amb,--auto-map-bindings", auto_map_bindings,
               "SPIR-V: give samplers and blocks without layout(binding) one (default with -G)");
  app.add_flag("-R", relaxed, "SPIR-V for Vulkan: relaxed rules (default-block uniforms are gathered into a block)");
  app.add_flag("-g", debug_info, "SPIR-V: debug information (OpLine)");
  app.add_flag("--strict", strict, "warn about unannotated interface variables");
  app.add_flag("--Werror", werror, "treat warnings as errors (also -Werror)");
  app.add_flag("-w", no_warnings, "suppress warnings");
  app.add_option("--error-limit", error_limit, "stop after N errors (default 20), 0 for no limit (also -ferror-limit=N)");
  app.add_option("--diagnostics-format", diagnostics_format, "text or json")->check(CLI::IsMember({"text", "json"}));
  app.add_option("--color", color, "auto (on a terminal), always or never")->check(CLI::IsMember({"auto", "always", "never"}));
  app.set_version_flag("--version", std::string(kCompilerName) + " " + std::string(kCompilerVersion));

  std::vector<std::string> args = normalise(raw_args);
  std::reverse(args.begin(), args.end());  // CLI11 takes them in reverse order
  try {
    app.parse(args);
  } catch (const CLI::CallForHelp&) {
    io.out << app.help();
    return 0;
  } catch (const CLI::CallForVersion&) {
    io.out << kCompilerName << " " << kCompilerVersion << "\n";
    return 0;
  } catch (const CLI::ParseError& e) {
    io.err << usage_error_text("safeglslc", e.what(), code::E_COMMAND_LINE);
    return kExitUsage;
  }

  std::optional<Stage> forced_stage;
  if (!stage_name.empty()) {
    forced_stage = stage_from_name(stage_name);
    if (!forced_stage) {
      return driver_error(io, code::E_COMMAND_LINE, "unknown stage '", stage_name, "' (expected one of ", stage_words, ")");
    }
  }
  std::optional<GlslVersion> override_version;
  if (!glsl_version.empty()) {
    override_version = parse_glsl_version(glsl_version);
    if (!override_version) {
      return driver_error(io, code::E_COMMAND_LINE, "unknown --glsl-version '", glsl_version,
                          "' (expected 100, 110, 120, 130, 140, 150, 300es, 310es, 320es, 330, 400, 410, 420, 430, 440, "
                          "450 or 460)");
    }
  }
  std::optional<SpirvOptions> spirv;
  if (!client.empty()) {
    spirv.emplace();
    if (!apply_client(client, *spirv)) {
      return driver_error(io, code::E_COMMAND_LINE, "unknown --client '", client, "' (expected vulkan100 or opengl100)");
    }
  }
  // The environments first, then the SPIR-V versions, whatever their order on the line.
  std::stable_partition(target_envs.begin(), target_envs.end(),
                        [](const std::string& env) { return env.rfind("spirv", 0) != 0; });
  for (const std::string& env : target_envs) {
    SpirvOptions candidate = spirv.value_or(SpirvOptions{});
    if (!apply_target_env(env, candidate)) {
      return driver_error(io, code::E_COMMAND_LINE, "unknown --target-env '", env,
                          "' (expected vulkan1.0, vulkan1.1, vulkan1.2, vulkan1.3, opengl or spirv1.0 ... spirv1.6)");
    }
    if (!spirv && env.rfind("spirv", 0) == 0) {
      return driver_error(io, code::E_COMMAND_LINE, "--target-env ", env, " sets the SPIR-V version; give -V or -G too");
    }
    spirv = candidate;
  }
  // The environment (Vulkan or OpenGL rules) and the output form are independent: -V, -G and
  // --client write SPIR-V; --target-env alone writes what the outputs are named.
  bool write_spirv = spirv.has_value();
  if (spirv && client.empty()) {
    const std::optional<bool> form = target_env_writes_spirv(outputs);
    if (!form) {
      return driver_error(io, code::E_COMMAND_LINE,
                          "some -o outputs are named .spv and some are not; with --target-env the names choose "
                          "SPIR-V (.spv) or plain GLSL for every input alike");
    }
    write_spirv = *form;
  }
  if (spirv && !write_spirv && spirv->client == SpirvClient::opengl) spirv.reset();  // plain OpenGL GLSL: the default rules
  if (write_spirv) {
    if (auto_map_locations) spirv->auto_map_locations = true;
    if (auto_map_bindings) spirv->auto_map_bindings = true;
    spirv->relaxed_vulkan_rules = relaxed;
    spirv->debug_info = debug_info;
  } else if (auto_map_locations || auto_map_bindings || relaxed || debug_info) {
    return driver_error(io, code::E_COMMAND_LINE,
                        "--aml, --amb, -R and -g are for SPIR-V output; give -V or -G too (or name the outputs .spv)");
  }
  if (write_spirv && !spirv_backend) {
    return driver_error(io, code::E_SPIRV,
                        "this safeglslc cannot write SPIR-V (it is safeglslc-spirv's job, which was not found beside it)");
  }

  if (!outputs.empty() && outputs.size() != files.size()) {
    return driver_error(io, code::E_COMMAND_LINE, outputs.size(), " -o given for ", files.size(),
                        " inputs; give one per input, in order");
  }

  std::vector<ShaderSource> sources;
  for (const std::string& path : files) {
    ShaderSource s;
    s.stage = forced_stage;
    if (path == "-") {
      if (!forced_stage) {
        return driver_error(io, code::E_PROGRAM, "reading stdin needs the stage: give -S ", stage_extension_list("|"));
      }
      s.path = "<stdin>";
      std::ostringstream text;
      text << io.in.rdbuf();
      s.text = text.str();
    } else {
      std::optional<std::string> text = read_file(path);
      if (!text) return driver_error(io, code::E_FILE, "cannot read '", path, "'");
      s.path = path;
      s.text = std::move(*text);
      if (!forced_stage && !stage_from_path(path)) {
        return driver_error(io, code::E_PROGRAM, "cannot tell the stage of '", path, "' from its extension (",
                            stage_extension_list(" ", "."), ", optionally after .sgl); use -S");
      }
    }
    sources.push_back(std::move(s));
  }

  CompileOptions options;
  options.include_paths = include_paths;
  for (const std::string& d : defines) options.defines.push_back(split_define(d));
  options.undefines = undefines;
  options.strict = strict;
  options.diagnostics.warnings_as_errors = werror;
  options.diagnostics.suppress_warnings = no_warnings;
  options.diagnostics.error_limit = error_limit;
  if (desktop_default) options.default_version = GlslVersion{110, false};
  options.override_version = override_version;
  if (spirv && spirv->client == SpirvClient::vulkan) options.vulkan = spirv->client_version;
  options.emit = !outputs.empty() || !symbols_path.empty() || write_spirv;
  CompileResult result = compile(sources, options);

  if (diagnostics_format == "json") {
    io.err << result.diagnostics_json() << "\n";
  } else if (!result.diagnostics.empty()) {
    const char* no_color = std::getenv("NO_COLOR");
    const bool use_color = color == "always" || (color == "auto" && io.err_is_terminal && no_color == nullptr);
    io.err << result.diagnostics_text(use_color);
    const std::size_t errors = result.error_count(), warnings = result.warning_count();
    if (warnings) io.err << warnings << (warnings == 1 ? " warning" : " warnings") << (errors ? " and " : " generated.\n");
    if (errors) io.err << errors << (errors == 1 ? " error" : " errors") << " generated.\n";
  }
  if (!result.success) return kExitDiagnostics;

  std::vector<std::string> texts;
  for (const StageOutput& stage : result.stages) texts.push_back(stage.glsl);
  if (write_spirv) {
    SpirvResult modules = spirv_backend(result, *spirv);
    io.err << modules.log;
    if (!modules.success) {
      const std::size_t errors = count_errors(modules.log);
      io.err << errors << (errors == 1 ? " error" : " errors") << " generated (glslang, on the emitted GLSL).\n";
      return kExitDiagnostics;
    }
    texts.clear();
    for (const SpirvModule& module : modules.modules) texts.push_back(spirv_bytes(module.words));
    // glslangValidator's default names: vert.spv, frag.spv, ...
    if (outputs.empty())
      for (const StageOutput& stage : result.stages) outputs.push_back(std::string(stage_extension(stage.stage)) + ".spv");
  }

  bool written = true;
  for (std::size_t i = 0; i < outputs.size(); ++i) written = write_output(outputs[i], texts[i], io) && written;
  if (!symbols_path.empty()) written = write_output(symbols_path, result.symbols_json(), io) && written;
  if (write_depfile) {
    // The depfile's target is the first file written (what the build rule produces).
    std::string target = !outputs.empty() && outputs.front() != "-" ? outputs.front() : symbols_path;
    if (target.empty() || target == "-") {
      return driver_error(io, code::E_COMMAND_LINE,
                          "-MD needs an output file (-o or --symbols) to name as the depfile's target");
    }
    const std::string path = depfile_path.empty() ? target + ".d" : depfile_path;
    written = write_output(path, depfile_text(target, result.dependencies), io) && written;
  }
  return written ? 0 : kExitUsage;
}

}  // namespace safegi
