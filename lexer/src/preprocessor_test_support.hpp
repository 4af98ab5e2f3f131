#pragma once
// Shared fixture of the preprocessor tests: in-memory files, the output as
// text, and the diagnostics rendered exactly as users see them.

#include <gtest/gtest.h>

#include <map>
#include <string>

#include <safegi/diagnostics/render.hpp>
#include <safegi/lexer/preprocessor.hpp>

namespace safegi::testing {

class PreprocessorTest : public ::testing::Test {
 protected:
  PreprocessorTest() {
    options.read_file = [this](const std::string& path) -> std::optional<std::string> {
      auto it = files.find(path);
      if (it == files.end()) return std::nullopt;
      return it->second;
    };
  }

  PreprocessedUnit run(std::string source, std::string path = "main.glsl") {
    main = sources.add_file(std::move(path), std::move(source));
    return preprocess(sources, main, options, diagnostics);
  }

  // The output tokens' spellings separated by spaces, each source line on its own line.
  static std::string spell(const PreprocessedUnit& unit) {
    std::string out;
    for (const Token& t : unit.tokens) {
      if (t.kind == TokenKind::eof) break;
      if (!out.empty()) out += t.at_line_start ? '\n' : ' ';
      out += t.text;
    }
    return out;
  }

  std::string output(std::string source) { return spell(run(std::move(source))); }
  std::string errors() const { return render_text(diagnostics.diagnostics(), sources); }

  std::map<std::string, std::string> files;
  PreprocessorOptions options;
  SourceManager sources;
  DiagnosticEngine diagnostics;
  FileId main = kNoFile;
};

}  // namespace safegi::testing
