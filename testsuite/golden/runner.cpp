// Golden-file runner: every shader under cases/ is one case. safeglslc runs
// in-process on it (cases/ is the working directory, so paths in messages are
// relative), and its exit status, stderr, stdout, emitted GLSL and (when asked)
// symbol table must equal <case>.expected byte for byte. Every emitted shader
// must also be accepted by glslang.
//
//   safegi_golden_runner <cases-dir> [--update] [--filter <substring>]
//
// Directives in the case's leading `//` comment lines:
//   // ARGS: <flags>       extra safeglslc flags, before the file
//   // WITH: <file>...     other stages compiled with it (program mode), before it
//   // STDIN               the case is fed on stdin as `-` (give -S in ARGS)
//   // SYMBOLS             also compare the JSON symbol table
//   // RAW                 pass only ARGS and the file: no -o / --symbols added
// --update rewrites the .expected files; review `git diff` before committing.

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "glslang_check.hpp"
#include "safegi/compiler/cli.hpp"
#include "safegi/compiler/compile.hpp"
#include "safegi/compiler/spirv.hpp"

namespace fs = std::filesystem;

namespace {

struct Case {
  fs::path path;  // relative to the cases directory
  std::vector<std::string> args, with;
  bool stdin_input = false, symbols = false, raw = false;
};

std::vector<std::string> split_words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

bool is_case(const fs::path& p) {
  const std::string name = p.filename().string();
  if (name.ends_with(".expected")) return false;
  return safegi::stage_from_path(name).has_value() || name.ends_with(".sgl") || name.ends_with(".glsl");
}

Case read_case(const fs::path& path) {
  Case c;
  c.path = path;
  std::istringstream text(safegi::testing::read_text_file(path));
  for (std::string line; std::getline(text, line) && line.rfind("//", 0) == 0;) {
    auto directive = [&](std::string_view name) {
      const std::string prefix = "// " + std::string(name);
      return line.rfind(prefix, 0) == 0 ? std::optional<std::string>(line.substr(prefix.size())) : std::nullopt;
    };
    if (auto v = directive("ARGS:")) c.args = split_words(*v);
    else if (auto w = directive("WITH:")) c.with = split_words(*w);
    else if (directive("STDIN")) c.stdin_input = true;
    else if (directive("SYMBOLS")) c.symbols = true;
    else if (directive("RAW")) c.raw = true;
  }
  return c;
}

std::optional<safegi::Stage> stage_of(const Case& c, const std::string& input) {
  for (std::size_t i = 0; i + 1 < c.args.size(); ++i)
    if (c.args[i] == "-S") return safegi::stage_from_name(c.args[i + 1]);
  return safegi::stage_from_path(input);
}

// Runs the case; returns the actual text to compare, or sets `problem`.
std::string run_case(const Case& c, const fs::path& scratch, std::string& problem) {
  std::vector<std::string> inputs = c.with;
  inputs.push_back(c.stdin_input ? "-" : c.path.generic_string());
  std::vector<std::string> args = c.args;
  std::vector<std::string> outputs;
  args.insert(args.end(), inputs.begin(), inputs.end());
  if (!c.raw) {
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      outputs.push_back((scratch / ("out" + std::to_string(i) + ".glsl")).string());
      args.push_back("-o");
      args.push_back(outputs.back());
    }
    args.push_back("--symbols");
    args.push_back((scratch / "symbols.json").string());
  }
  std::istringstream in(c.stdin_input ? safegi::testing::read_text_file(c.path) : std::string());
  std::ostringstream out, err;
  safegi::CliStreams io{in, out, err, false};
  const int status = safegi::run_safeglslc(args, io, &safegi::to_spirv);

  std::string actual = "exit: " + std::to_string(status) + "\n";
  actual += "--- stderr\n" + err.str();
  if (!out.str().empty()) actual += "--- stdout\n" + out.str();
  if (status == 0 && !c.raw) {
    for (std::size_t i = 0; i < outputs.size(); ++i) {
      const std::string glsl = safegi::testing::read_text_file(outputs[i]);
      actual += "--- glsl " + inputs[i] + "\n" + glsl;
      if (std::optional<safegi::Stage> stage = stage_of(c, inputs[i])) {
        safegi::testing::GlslangVerdict verdict = safegi::testing::glslang_validate(glsl, *stage);
        if (!verdict.accepted) problem += "glslang rejects the GLSL emitted for " + inputs[i] + ":\n" + verdict.log;
      }
    }
    if (c.symbols) actual += "--- symbols\n" + safegi::testing::read_text_file(scratch / "symbols.json");
  }
  for (const std::string& o : outputs) fs::remove(o);
  fs::remove(scratch / "symbols.json");
  return actual;
}

// The first line where the two texts differ, for the failure message.
std::string first_difference(const std::string& expected, const std::string& actual) {
  std::istringstream e(expected), a(actual);
  std::string le, la;
  for (int line = 1;; ++line) {
    const bool he = static_cast<bool>(std::getline(e, le));
    const bool ha = static_cast<bool>(std::getline(a, la));
    if (!he && !ha) return "texts differ only in the final newline";
    if (!he || !ha || le != la)
      return "line " + std::to_string(line) + ":\n  expected: " + (he ? le : "<end>") + "\n  actual:   " + (ha ? la : "<end>");
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: safegi_golden_runner <cases-dir> [--update] [--filter <substring>]\n";
    return 2;
  }
  const fs::path root = fs::absolute(argv[1]);
  bool update = false;
  std::string filter;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--update") update = true;
    else if (a == "--filter" && i + 1 < argc) filter = argv[++i];
    else {
      std::cerr << "safegi_golden_runner: unknown argument '" << a << "'\n";
      return 2;
    }
  }
  const fs::path scratch = fs::temp_directory_path() / ("safegi-golden-" + std::to_string(::getpid()));
  fs::create_directories(scratch);
  fs::current_path(root);

  std::vector<fs::path> cases;
  for (const auto& entry : fs::recursive_directory_iterator("."))
    if (entry.is_regular_file() && is_case(entry.path()) && entry.path().generic_string().find("/inputs/") == std::string::npos)
      cases.push_back(entry.path().lexically_normal());
  std::sort(cases.begin(), cases.end());

  int failed = 0, ran = 0, updated = 0;
  for (const fs::path& path : cases) {
    if (!filter.empty() && path.generic_string().find(filter) == std::string::npos) continue;
    ++ran;
    const Case c = read_case(path);
    std::string problem;
    const std::string actual = run_case(c, scratch, problem);
    const fs::path expected_path = path.string() + ".expected";
    if (update) {
      if (!fs::exists(expected_path) || safegi::testing::read_text_file(expected_path) != actual) {
        std::ofstream(expected_path, std::ios::binary) << actual;
        std::cout << "updated " << expected_path.generic_string() << "\n";
        ++updated;
      }
    } else if (!fs::exists(expected_path)) {
      problem += "no " + expected_path.generic_string() + " (run with --update, then review it)\n";
    } else if (const std::string expected = safegi::testing::read_text_file(expected_path); expected != actual) {
      problem += "output differs from " + expected_path.generic_string() + ", " + first_difference(expected, actual) + "\n";
    }
    if (!problem.empty()) {
      ++failed;
      std::cout << "FAIL " << path.generic_string() << "\n" << problem << "\n";
    }
  }
  fs::remove_all(scratch);
  std::cout << ran << " golden cases, " << failed << " failed" << (update ? ", " + std::to_string(updated) + " updated" : "")
            << "\n";
  return failed == 0 && ran > 0 ? 0 : 1;
}
