#include "test_support.hpp"

#include <safegi/diagnostics/file.hpp>
#include <safegi/diagnostics/render.hpp>
#include <safegi/lexer/lexer.hpp>

namespace safegi::testing {

std::vector<std::string> CheckedSource::messages() const {
  std::vector<std::string> out;
  for (const Diagnostic& d : diagnostics.diagnostics())
    out.push_back(std::string(severity_name(d.severity)) + ": " + d.message);
  return out;
}

std::string CheckedSource::rendered() const { return render_text(diagnostics.diagnostics(), sources); }

std::unique_ptr<CheckedSource> check_source(std::string_view source, SourceOptions options) {
  auto c = std::make_unique<CheckedSource>();
  if (options.prelude) {
    FileId prelude = c->sources.add_file("prelude.sgl", read_file(SAFEGI_PRELUDE_FILE).value_or(""));
    c->tokens = tokenize(c->sources, prelude, c->diagnostics);
    if (!c->tokens.empty()) c->tokens.pop_back();  // its eof
  }
  FileId file = c->sources.add_file("test.frag", std::string(source));
  std::vector<Token> main = tokenize(c->sources, file, c->diagnostics);
  c->tokens.insert(c->tokens.end(), main.begin(), main.end());
  c->parsed = parse(c->tokens, c->diagnostics);
  CheckOptions check_options;
  check_options.stage = options.stage;
  check_options.strict = options.strict;
  check_options.language = options.language;
  check_options.record_symbols = options.symbols;
  check_options.tokens = &c->tokens;  // as the compiler passes them: hints quote the program's own code
  check_options.sources = &c->sources;
  c->result = check(*c->parsed.unit, check_options, c->diagnostics);
  return c;
}

std::string declared_type(const CheckedSource& c, std::string_view name) {
  for (const auto& [decl, type] : c.result.declarators)
    if (decl->name == name) return c.result.describe(type);
  return "<not declared>";
}

}  // namespace safegi::testing
