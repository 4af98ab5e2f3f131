// Checks one annotated shader (preprocess, parse, type check) and prints its
// diagnostics exactly as safeglslc would; with --expect, compares them with a
// file and fails on any difference; with --update, rewrites that file.
//
//   safegi_check_file [--strict] [-I dir]... [--expect out.txt [--update]] shader.sgl.frag

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <safegi/diagnostics/render.hpp>
#include <safegi/diagnostics/source_manager.hpp>
#include <safegi/lexer/preprocessor.hpp>
#include <safegi/parser/parser.hpp>
#include <safegi/typechecker/checker.hpp>

namespace {

safegi::Stage stage_of(const std::string& path) {
  auto ends = [&](const char* ext) {
    const std::string e = ext;
    return path.size() >= e.size() && path.compare(path.size() - e.size(), e.size(), e) == 0;
  };
  if (ends(".vert")) return safegi::Stage::vertex;
  if (ends(".frag")) return safegi::Stage::fragment;
  if (ends(".geom")) return safegi::Stage::geometry;
  if (ends(".comp")) return safegi::Stage::compute;
  if (ends(".tesc")) return safegi::Stage::tess_control;
  if (ends(".tese")) return safegi::Stage::tess_evaluation;
  return safegi::Stage::unknown;
}

int usage() {
  std::cerr << "usage: safegi_check_file [--strict] [-I dir]... [--expect file [--update]] shader\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> includes{SAFEGI_PRELUDE_DIR};
  std::string expect, shader;
  bool update = false, strict = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--strict") strict = true;
    else if (a == "--update") update = true;
    else if (a == "--expect" && i + 1 < argc) expect = argv[++i];
    else if (a == "-I" && i + 1 < argc) includes.push_back(argv[++i]);
    else if (!a.empty() && a[0] != '-' && shader.empty()) shader = a;
    else return usage();
  }
  if (shader.empty()) return usage();

  safegi::SourceManager sources;
  safegi::DiagnosticEngine diagnostics;
  std::string error;
  std::optional<safegi::FileId> file = sources.load_file(shader, &error);
  if (!file) {
    std::cerr << shader << ": " << error << "\n";
    return 2;
  }
  safegi::PreprocessorOptions pp;
  pp.include_paths = includes;
  safegi::PreprocessedUnit unit = safegi::preprocess(sources, *file, pp, diagnostics);
  safegi::ParseResult parsed = safegi::parse(unit.tokens, diagnostics);
  if (!diagnostics.has_errors()) {
    safegi::CheckOptions options;
    options.stage = stage_of(shader);
    options.strict = strict;
    options.tokens = &unit.tokens;
    options.sources = &sources;
    safegi::check(*parsed.unit, options, diagnostics);
  }
  const std::string text = safegi::render_text(diagnostics.diagnostics(), sources);
  if (expect.empty()) {
    std::cout << text;
    return diagnostics.has_errors() ? 1 : 0;
  }
  if (update) {
    std::ofstream(expect, std::ios::binary) << text;
    return 0;
  }
  std::ifstream in(expect, std::ios::binary);
  if (!in) {
    std::cerr << expect << ": cannot read the expected output (run with --update to create it)\n";
    return 2;
  }
  std::stringstream want;
  want << in.rdbuf();
  if (want.str() == text) return 0;
  std::cout << "--- expected (" << expect << ")\n" << want.str() << "--- actual\n" << text;
  return 1;
}
