// Measures the front end on shaders nobody here wrote (docs/frontend-corpus.md).
//
//   safegi_corpus_check glslang FILE...   which shaders glslang accepts, and
//                                         the share of those safeglslc's front
//                                         end parses and round-trips
//   safegi_corpus_check piglit FILE...    glslparsertest files: the share where
//                                         our syntax verdict agrees with
//                                         `expect_result`; with
//                                         SAFEGI_CORPUS_VERBOSE set, also lists
//                                         the expected failures it accepts
//   safegi_corpus_check robustness FILE... every file through the front end:
//                                         no crash, no hang (10 s watchdog)
//
// Round trip: preprocess + parse, print (with the #version and #extension
// lines), preprocess + parse the print, compare tree dumps; glslang must
// accept the print too.
//
// Type checker (docs/typechecker.md, "zero false positives on plain GLSL"):
// every glslang-accepted shader that parses is also type checked; any error
// the checker reports there is a false positive and is listed.

#include <algorithm>
#include <cctype>
#include <chrono>
#include <csignal>
#include <cstring>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <safegi/diagnostics/render.hpp>
#include <safegi/lexer/preprocessor.hpp>
#include <safegi/parser/parser.hpp>
#include <safegi/parser/printer.hpp>
#include <safegi/typechecker/checker.hpp>

namespace {

std::optional<EShLanguage> stage_of(const std::filesystem::path& path) {
  static const std::map<std::string, EShLanguage> stages = {
      {".vert", EShLangVertex},         {".frag", EShLangFragment},      {".geom", EShLangGeometry},
      {".comp", EShLangCompute},        {".tesc", EShLangTessControl},   {".tese", EShLangTessEvaluation}};
  auto it = stages.find(path.extension().string());
  if (it == stages.end()) return std::nullopt;
  return it->second;
}

int glslang_crashes = 0;

// glslang's verdicts never change for a given text and stage, and taking one
// costs a process: SAFEGI_CORPUS_GLSLANG_CACHE=FILE keeps them between runs
// (one line per shader: key, verdict code, first error).
struct CachedVerdict {
  int code = 0;  // glslang_verdict's child exit code: 0 accepted, 1 rejected, 2 syntax error, 3 crashed
  std::string first_error;
};
std::map<std::string, CachedVerdict> verdict_cache;
bool verdict_cache_dirty = false;

std::string cache_key(const std::string& text, EShLanguage stage) {
  return std::to_string(std::hash<std::string>{}(text)) + "-" + std::to_string(text.size()) + "-" +
         std::to_string(static_cast<int>(stage));
}

void load_verdict_cache() {
  const char* path = std::getenv("SAFEGI_CORPUS_GLSLANG_CACHE");
  if (!path) return;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::string key;
    CachedVerdict v;
    if (!(fields >> key >> v.code)) continue;
    std::getline(fields, v.first_error);
    if (!v.first_error.empty() && v.first_error[0] == ' ') v.first_error.erase(0, 1);
    verdict_cache[key] = v;
  }
}

void save_verdict_cache() {
  const char* path = std::getenv("SAFEGI_CORPUS_GLSLANG_CACHE");
  if (!path || !verdict_cache_dirty) return;
  std::ofstream out(path);
  for (const auto& [key, v] : verdict_cache) out << key << " " << v.code << " " << v.first_error << "\n";
}

enum class Verdict { accepted, rejected, syntax_error };
// `first_error`, when given, receives glslang's first "ERROR:" line.
Verdict glslang_verdict(const std::string& text, EShLanguage stage, std::string* first_error = nullptr);

bool glslang_accepts(const std::string& text, EShLanguage stage) {
  return glslang_verdict(text, stage) == Verdict::accepted;
}

std::string first_error_line(const std::string& log) {
  std::size_t at = log.find("ERROR:");
  if (at == std::string::npos) return "";
  return log.substr(at, log.find('\n', at) - at);
}

// Debian's glslang 12 crashes on a few newer test files of its own Test/
// folder, so each verdict is taken in a child process; a crash counts as
// "not accepted".
Verdict verdict_of_code(int code) {
  return code == 0 ? Verdict::accepted : code == 2 ? Verdict::syntax_error : Verdict::rejected;
}

Verdict glslang_verdict_uncached(const std::string& text, EShLanguage stage, std::string* first_error);

Verdict glslang_verdict(const std::string& text, EShLanguage stage, std::string* first_error) {
  const std::string key = cache_key(text, stage);
  if (auto it = verdict_cache.find(key); it != verdict_cache.end()) {
    if (it->second.code == 3) ++glslang_crashes;
    if (first_error) *first_error = it->second.first_error;
    return verdict_of_code(it->second.code);
  }
  std::string error;
  const int crashes = glslang_crashes;
  Verdict v = glslang_verdict_uncached(text, stage, &error);
  if (first_error) *first_error = error;
  CachedVerdict cached{v == Verdict::accepted ? 0 : v == Verdict::syntax_error ? 2 : 1, error};
  if (glslang_crashes != crashes) cached.code = 3;
  for (char& c : cached.first_error)
    if (c == '\n' || c == '\r') c = ' ';
  verdict_cache[key] = cached;
  verdict_cache_dirty = true;
  return v;
}

Verdict glslang_verdict_uncached(const std::string& text, EShLanguage stage, std::string* first_error) {
  std::fflush(stdout);
  int message_pipe[2] = {-1, -1};
  if (first_error && pipe(message_pipe) != 0) first_error = nullptr;
  pid_t child = fork();
  if (child == 0) {
    int null = open("/dev/null", O_WRONLY);  // glslang prints its own complaints
    dup2(null, 1);
    dup2(null, 2);
    glslang::TShader shader(stage);
    const char* source = text.c_str();
    shader.setStrings(&source, 1);
    // Without #version a shader is GLSL 1.10, as for our preprocessor.
    if (shader.parse(GetDefaultResources(), 110, false, EShMsgDefault)) _exit(0);
    std::string log = shader.getInfoLog();
    if (first_error) {
      std::string line = first_error_line(log).substr(0, 512);
      if (write(message_pipe[1], line.data(), line.size()) < 0) _exit(1);
    }
    _exit(log.find("syntax error") != std::string::npos ? 2 : 1);
  }
  if (first_error) {
    close(message_pipe[1]);
    char buffer[600];
    ssize_t n = child > 0 ? read(message_pipe[0], buffer, sizeof buffer) : 0;
    *first_error = n > 0 ? std::string(buffer, static_cast<std::size_t>(n)) : "";
    close(message_pipe[0]);
  }
  int status = 0;
  if (child < 0 || waitpid(child, &status, 0) != child) return Verdict::rejected;
  if (WIFSIGNALED(status)) {
    ++glslang_crashes;
    return Verdict::rejected;
  }
  if (!WIFEXITED(status)) return Verdict::rejected;
  return verdict_of_code(WEXITSTATUS(status));
}

safegi::Stage checker_stage(EShLanguage stage) {
  switch (stage) {
    case EShLangVertex: return safegi::Stage::vertex;
    case EShLangFragment: return safegi::Stage::fragment;
    case EShLangGeometry: return safegi::Stage::geometry;
    case EShLangCompute: return safegi::Stage::compute;
    case EShLangTessControl: return safegi::Stage::tess_control;
    case EShLangTessEvaluation: return safegi::Stage::tess_evaluation;
    default: return safegi::Stage::unknown;
  }
}

struct FrontEnd {
  bool ok = false;          // preprocess + parse succeeded (the syntax verdict)
  bool checked = false;     // the type checker reported no error (only when ok)
  bool valid() const { return ok && checked; }  // the validating front end's verdict
  std::string first_check_error;
  std::string first_error;  // rendered, one line
  std::string dump;
  std::string printed;      // with #version / #extension preamble
  int version = 110;
  bool es = false;
};

std::string first_error_of(const safegi::DiagnosticEngine& diagnostics, const safegi::SourceManager& sources) {
  for (const safegi::Diagnostic& d : diagnostics.diagnostics()) {
    if (d.severity != safegi::Severity::error) continue;
    std::string text = safegi::render_text(d, sources);
    return text.substr(0, text.find('\n'));
  }
  return "";
}

// As safeglslc runs it (compiler/src/compile.cpp): the #version and
// extensions reach the parser's and the checker's gates unless the
// preprocessor reported an error (the level is a guess then).
FrontEnd run_front_end(const std::string& name, const std::string& text, const std::string& include_dir,
                       EShLanguage stage) {
  FrontEnd result;
  safegi::SourceManager sources;
  safegi::DiagnosticEngine diagnostics;
  safegi::FileId file = sources.add_file(name, text);
  safegi::PreprocessorOptions options;
  if (!include_dir.empty()) options.include_paths.push_back(include_dir);
  safegi::PreprocessedUnit unit = safegi::preprocess(sources, file, options, diagnostics);
  const bool preprocessed = !diagnostics.has_errors();
  safegi::ParseOptions parse_options;
  parse_options.language = unit.language;
  safegi::ParseResult parsed = safegi::parse(unit.tokens, diagnostics, parse_options);
  result.version = unit.version;
  result.es = unit.es;
  result.ok = !diagnostics.has_errors();
  if (!result.ok) {
    result.first_error = first_error_of(diagnostics, sources);
    return result;
  }
  result.dump = safegi::dump_ast(*parsed.unit);
  safegi::DiagnosticEngine check_diagnostics;
  safegi::CheckOptions check_options{.stage = checker_stage(stage)};
  if (preprocessed) check_options.language = unit.language;
  check_options.version_range = unit.version_range;
  safegi::check(*parsed.unit, check_options, check_diagnostics);
  result.checked = !check_diagnostics.has_errors();
  result.first_check_error = first_error_of(check_diagnostics, sources);
  safegi::PrintOptions print;
  if (unit.version_given) {
    print.preamble = "#version " + std::to_string(unit.version);
    if (!unit.profile.empty()) print.preamble += " " + unit.profile;
    print.preamble += "\n";
  }
  for (const safegi::ExtensionDirective& e : unit.extensions) {
    print.preamble += "#extension " + e.name + " : " + e.behavior + "\n";
  }
  result.printed = safegi::print_glsl(*parsed.unit, print);
  return result;
}

// SAFEGI_CORPUS_VERDICTS=FILE: one line per shader, "accept|reject CORPUS PATH"
// (CORPUS: glslang, or piglit-pass / piglit-fail by expect_result), to diff
// two runs for new false positives.
std::ofstream* verdict_list() {
  static std::ofstream* out = [] {
    const char* path = std::getenv("SAFEGI_CORPUS_VERDICTS");
    return path ? new std::ofstream(path, std::ios::app) : nullptr;
  }();
  return out;
}

void list_verdict(bool accepted, const char* corpus, const std::filesystem::path& path) {
  if (std::ofstream* out = verdict_list()) *out << (accepted ? "accept " : "reject ") << corpus << " " << path.string() << std::endl;
}

// glslang's message without its location and the names it quotes, so that
// messages of one kind group together: "'=' :  l-value required "buf"" -> "'_' : l-value required _".
std::string error_class(const std::string& error) {
  std::string text = error;
  if (text.rfind("ERROR: ", 0) == 0) text = text.substr(7);
  // "0:12: " (string:line:)
  std::size_t colon = text.find(": ");
  if (colon != std::string::npos && colon < 12 && std::isdigit(static_cast<unsigned char>(text[0]))) text = text.substr(colon + 2);
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\'' || c == '"') {
      std::size_t end = text.find(c, i + 1);
      if (end == std::string::npos) break;
      out += c;
      out += '_';
      out += c;
      i = end;
    } else if (std::isdigit(static_cast<unsigned char>(c))) {
      if (out.empty() || out.back() != '#') out += '#';
    } else if (c == ' ' && !out.empty() && out.back() == ' ') {
      continue;
    } else {
      out += c;
    }
  }
  return out;
}

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// `// [config]` ... `// [end config]` of a piglit glslparsertest file.
std::optional<std::string> piglit_expectation(const std::string& text) {
  std::size_t begin = text.find("[config]");
  if (begin == std::string::npos) return std::nullopt;
  std::size_t end = text.find("[end config]", begin);
  std::string config = text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
  std::size_t key = config.find("expect_result:");
  if (key == std::string::npos) return std::nullopt;
  std::istringstream value(config.substr(key + 14));
  std::string word;
  value >> word;
  if (word != "pass" && word != "fail") return std::nullopt;
  return word;
}

bool modern(const FrontEnd& f) { return f.es ? f.version >= 300 : f.version >= 330; }

struct Tally {
  int total = 0, parsed = 0, round_tripped = 0, printed_accepted = 0, checked = 0;
  void print(const char* label) const {
    auto pct = [&](int n) { return total ? 100.0 * n / total : 0.0; };
    std::printf("  %-28s %5d   parsed %5d (%6.2f%%)   round-tripped %5d (%6.2f%%)   print accepted by glslang %5d (%6.2f%%)"
                "   type checked clean %5d (%6.2f%%)\n",
                label, total, parsed, pct(parsed), round_tripped, pct(round_tripped), printed_accepted,
                pct(printed_accepted), checked, pct(checked));
  }
};

// Parse, print, re-parse one shader glslang accepts; tallies and notes
// failures. Returns the validating front end's verdict on it.
bool check_round_trip(const std::filesystem::path& path, const std::string& text, EShLanguage stage, Tally& all,
                      Tally& recent, std::vector<std::string>& failures, std::vector<std::string>& false_positives) {
  FrontEnd first = run_front_end(path.string(), text, path.parent_path().string(), stage);
  bool is_modern = first.ok ? modern(first) : true;
  ++all.total;
  recent.total += is_modern;
  if (!first.ok) {
    failures.push_back(path.string() + ": parse: " + first.first_error);
    return false;
  }
  if (!first.checked) false_positives.push_back(path.string() + ": " + first.first_check_error);
  FrontEnd second = run_front_end(path.string() + ".printed", first.printed, path.parent_path().string(), stage);
  bool same = second.ok && second.dump == first.dump;
  bool accepted = glslang_accepts(first.printed, stage);
  for (Tally* t : {&all, is_modern ? &recent : nullptr}) {
    if (!t) continue;
    ++t->parsed;
    t->round_tripped += same;
    t->printed_accepted += accepted;
    t->checked += first.checked;
  }
  if (!same) {
    failures.push_back(path.string() + ": round trip: " +
                       (second.ok ? std::string("tree differs after printing") : second.first_error));
  } else if (!accepted) {
    failures.push_back(path.string() + ": printed GLSL rejected by glslang");
  }
  return first.valid();
}

void print_round_trips(const Tally& all, const Tally& recent, const std::vector<std::string>& failures,
                       const std::vector<std::string>& false_positives) {
  all.print("accepted by glslang:");
  recent.print("of which #version>=330/300es:");
  std::printf("failures (%zu):\n", failures.size());
  for (const std::string& f : failures) std::printf("  %s\n", f.c_str());
  std::printf("type checker: %d of %d glslang-accepted shaders that parse check clean\n", all.checked, all.parsed);
  std::printf("type checker false positives (%zu):\n", false_positives.size());
  for (const std::string& f : false_positives) std::printf("  %s\n", f.c_str());
}

int run_glslang_mode(const std::vector<std::filesystem::path>& files) {
  Tally all, recent;
  int considered = 0, rejected_by_glslang = 0;
  std::vector<std::string> failures, false_positives;
  for (const auto& path : files) {
    auto stage = stage_of(path);
    if (!stage) continue;
    ++considered;
    std::string text = read(path);
    if (!glslang_accepts(text, *stage)) {
      ++rejected_by_glslang;
      continue;
    }
    list_verdict(check_round_trip(path, text, *stage, all, recent, failures, false_positives), "glslang", path);
  }
  std::printf("glslang corpus: %d shaders considered, %d rejected by glslang (not counted; %d of them crashed it), %d accepted\n",
              considered, rejected_by_glslang, glslang_crashes, all.total);
  print_round_trips(all, recent, failures, false_positives);
  return 0;
}

struct PiglitTally {
  int agree = 0, pass_pass = 0, pass_fail = 0, fail_fail = 0, fail_pass = 0, syntax_fail_rejected = 0;
  void add(bool accepted, bool expect_pass, bool glslang_syntax_error) {
    agree += accepted == expect_pass;
    if (expect_pass) {
      accepted ? ++pass_pass : ++pass_fail;
    } else {
      accepted ? ++fail_pass : ++fail_fail;
      syntax_fail_rejected += glslang_syntax_error && !accepted;
    }
  }
};

int run_piglit_mode(const std::vector<std::filesystem::path>& files) {
  int total = 0, glslang_agree = 0, syntax_fail = 0;
  PiglitTally validated, syntax;  // preprocess + parse + check, and preprocess + parse only
  std::vector<std::string> syntax_missed;
  std::vector<std::string> ours_rejects_valid;
  // Expected to fail and accepted, by the class of glslang's first error: count and the shaders.
  std::map<std::string, std::vector<std::string>> accepted_failures;
  bool verbose = std::getenv("SAFEGI_CORPUS_VERBOSE") != nullptr;
  Tally all, recent;  // round trips of the shaders glslang accepts, whatever piglit expects
  std::vector<std::string> round_trip_failures, false_positives, rejected_as_piglit_expects;
  int checked_total = 0;
  for (const auto& path : files) {
    auto stage = stage_of(path);
    if (!stage) continue;
    std::string text = read(path);
    auto expectation = piglit_expectation(text);
    if (!expectation) continue;
    ++total;
    bool expect_pass = *expectation == "pass";
    FrontEnd ours = run_front_end(path.string(), text, path.parent_path().string(), *stage);
    std::string glslang_error;
    Verdict verdict = glslang_verdict(text, *stage, &glslang_error);
    if (!expect_pass && ours.valid()) {
      accepted_failures[glslang_error.empty() ? "(glslang accepts it too)" : error_class(glslang_error)].push_back(
          path.string() + (glslang_error.empty() ? "" : " | " + glslang_error));
    }
    list_verdict(ours.valid(), expect_pass ? "piglit-pass" : "piglit-fail", path);
    bool glslang_ok = verdict == Verdict::accepted;
    if (glslang_ok) {
      const std::size_t before = false_positives.size();
      check_round_trip(path, text, *stage, all, recent, round_trip_failures, false_positives);
      ++checked_total;
      // glslang accepts some shaders piglit says must fail; the checker rejecting those is right.
      if (false_positives.size() > before && !expect_pass) {
        rejected_as_piglit_expects.push_back(false_positives.back());
        false_positives.pop_back();
      }
    }
    glslang_agree += glslang_ok == expect_pass;
    const bool glslang_syntax = !expect_pass && verdict == Verdict::syntax_error;
    syntax_fail += glslang_syntax;
    validated.add(ours.valid(), expect_pass, glslang_syntax);
    syntax.add(ours.ok, expect_pass, glslang_syntax);
    if (expect_pass && !ours.valid())
      ours_rejects_valid.push_back(path.string() + ": " + (ours.ok ? ours.first_check_error : ours.first_error));
    if (glslang_syntax && ours.ok) syntax_missed.push_back(path.string());
  }
  auto pct = [&](int n) { return total ? 100.0 * n / total : 0.0; };
  std::printf("piglit glslparsertest: %d shaders with expect_result\n", total);
  std::printf("  validating front end (preprocess + parse + check) agrees with expect_result: %d (%.2f%%)   "
              "[glslang, a full compiler: %d (%.2f%%)]\n",
              validated.agree, pct(validated.agree), glslang_agree, pct(glslang_agree));
  std::printf("    expect pass: we accept %d, we reject %d\n", validated.pass_pass, validated.pass_fail);
  std::printf("    expect fail: we reject %d, we accept %d\n", validated.fail_fail, validated.fail_pass);
  std::printf("  syntax only (preprocess + parse) agrees with expect_result: %d (%.2f%%)\n", syntax.agree, pct(syntax.agree));
  std::printf("    expect pass: we accept %d, we reject %d\n", syntax.pass_pass, syntax.pass_fail);
  std::printf("    expect fail: we reject %d, we accept %d\n", syntax.fail_fail, syntax.fail_pass);
  std::printf("  expect fail with a glslang *syntax error*: %d, of which the parser rejects %d (%.2f%%)\n", syntax_fail,
              syntax.syntax_fail_rejected, syntax_fail ? 100.0 * syntax.syntax_fail_rejected / syntax_fail : 0.0);
  std::printf("expected to fail with a glslang syntax error but accepted by the parser (%zu):\n", syntax_missed.size());
  for (const std::string& f : syntax_missed) std::printf("  %s\n", f.c_str());
  std::printf("expected to pass but rejected by the validating front end (%zu):\n", ours_rejects_valid.size());
  for (const std::string& f : ours_rejects_valid) std::printf("  %s\n", f.c_str());
  // Largest classes first.
  std::vector<std::pair<std::string, const std::vector<std::string>*>> classes;
  for (const auto& [name, list] : accepted_failures) classes.emplace_back(name, &list);
  std::stable_sort(classes.begin(), classes.end(),
                   [](const auto& a, const auto& b) { return a.second->size() > b.second->size(); });
  std::printf("expected to fail but accepted by the validating front end (%d), by glslang's first error%s:\n",
              validated.fail_pass, verbose ? "" : " (SAFEGI_CORPUS_VERBOSE=1 lists every shader)");
  for (const auto& [name, list] : classes) {
    std::printf("  %4zu  %s\n", list->size(), name.c_str());
    for (std::size_t i = 0; i < list->size() && (verbose || i < 1); ++i) std::printf("          %s\n", (*list)[i].c_str());
  }
  std::printf("piglit shaders glslang accepts, parsed and round-tripped:\n");
  print_round_trips(all, recent, round_trip_failures, false_positives);
  std::printf("type checker on piglit: %zu false positives among %d glslang-accepted shaders; %zu more rejected that glslang accepts "
              "but piglit expects to fail:\n",
              false_positives.size(), checked_total, rejected_as_piglit_expects.size());
  for (const std::string& f : rejected_as_piglit_expects) std::printf("  %s\n", f.c_str());
  return 0;
}

// The file being checked, for the watchdog's message.
char current_file[4096] = "";

void on_timeout(int) {
  const char prefix[] = "front end hangs (over 10 s) on ";
  if (write(2, prefix, sizeof prefix - 1) < 0 || write(2, current_file, std::strlen(current_file)) < 0) _exit(3);
  _exit(3);
}

// Every file through the front end and its printer, whatever glslang thinks
// of it (Vulkan, HLSL, shaders meant to fail): no crash, no hang. A crash
// ends the process (the caller sees it); a file over 10 s ends it with the
// file's name.
int run_robustness_mode(const std::vector<std::filesystem::path>& files) {
  std::signal(SIGALRM, on_timeout);
  int total = 0, accepted = 0;
  double slowest = 0;
  std::string slowest_file;
  for (const auto& path : files) {
    std::snprintf(current_file, sizeof current_file, "%s", path.string().c_str());
    std::string text = read(path);
    alarm(10);
    auto start = std::chrono::steady_clock::now();
    // Files of no known stage are still read (and checked) as vertex shaders: only a crash or hang counts here.
    EShLanguage stage = stage_of(path).value_or(EShLangVertex);
    FrontEnd first = run_front_end(path.string(), text, path.parent_path().string(), stage);
    if (first.ok) run_front_end(path.string() + ".printed", first.printed, path.parent_path().string(), stage);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    alarm(0);
    ++total;
    accepted += first.ok;
    if (seconds > slowest) {
      slowest = seconds;
      slowest_file = path.string();
    }
  }
  std::printf("robustness: %d files through the front end, %d accepted, %d rejected with diagnostics; "
              "no crash, no hang; slowest %.3f s (%s)\n",
              total, accepted, total - accepted, slowest, slowest_file.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string mode = argc >= 2 ? argv[1] : "";
  if (argc < 3 || (mode != "glslang" && mode != "piglit" && mode != "robustness")) {
    std::fprintf(stderr, "usage: %s glslang|piglit|robustness FILE|DIR|@LIST...\n", argv[0]);
    return 2;
  }
  std::vector<std::filesystem::path> files;
  for (int i = 2; i < argc; ++i) {
    std::string arg = argv[i];
    if (!arg.empty() && arg[0] == '@') {  // @LIST: one path per line
      std::ifstream list(arg.substr(1));
      for (std::string line; std::getline(list, line);) {
        if (!line.empty()) files.emplace_back(line);
      }
      continue;
    }
    std::filesystem::path p(arg);
    if (std::filesystem::is_directory(p)) {
      for (const auto& entry : std::filesystem::recursive_directory_iterator(p)) {
        if (entry.is_regular_file()) files.push_back(entry.path());
      }
    } else {
      files.push_back(p);
    }
  }
  std::sort(files.begin(), files.end());
  glslang::InitializeProcess();
  load_verdict_cache();
  int rc = mode == "glslang" ? run_glslang_mode(files) : mode == "piglit" ? run_piglit_mode(files)
                                                                          : run_robustness_mode(files);
  save_verdict_cache();
  glslang::FinalizeProcess();
  return rc;
}
