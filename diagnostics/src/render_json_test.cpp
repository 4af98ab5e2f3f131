#include <safegi/diagnostics/render.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace safegi {
namespace {

TEST(RenderJson, FieldsOfADiagnostic) {
  SourceManager sm;
  FileId f = sm.add_file("a.glsl", "float x = y;\n");
  Diagnostic d = Diagnostic::error(sm.range_of(f, 10, 11), "undeclared identifier 'y'")
                     .with_code("E-UNDECLARED")
                     .with_hint("declare it")
                     .with_note(Diagnostic::note(sm.range_of(f, 6, 7), "here"));
  auto j = nlohmann::json::parse(render_json(d, sm));
  EXPECT_EQ(j, nlohmann::json::parse(R"({
    "severity": "error", "message": "undeclared identifier 'y'", "code": "E-UNDECLARED", "hint": "declare it",
    "range": {"file": "a.glsl", "begin": {"line": 1, "column": 11, "offset": 10},
              "end": {"line": 1, "column": 12, "offset": 11}},
    "notes": [{"severity": "note", "message": "here",
               "range": {"file": "a.glsl", "begin": {"line": 1, "column": 7, "offset": 6},
                         "end": {"line": 1, "column": 8, "offset": 7}}}]})"));
}

TEST(RenderJson, ChainsAndList) {
  SourceManager sm;
  FileId main = sm.add_file("main.glsl", "#include \"a\"\n");
  FileId a = sm.add_file("a", "#define X y\nX\n");
  sm.set_included_from(a, sm.range_of(main, 0, 12));
  ExpansionId e = sm.add_expansion({"X", sm.range_of(a, 8, 9), sm.range_of(a, 12, 13), kNoExpansion});
  Diagnostic d = Diagnostic::error(sm.range_of(a, 10, 11), "e").with_expansion(e);
  auto j = nlohmann::json::parse(render_json(std::vector<Diagnostic>{d}, sm));
  ASSERT_EQ(j["diagnostics"].size(), 1u);
  const auto& first = j["diagnostics"][0];
  EXPECT_EQ(first["included_from"][0]["file"], "main.glsl");
  EXPECT_EQ(first["expansions"][0]["macro"], "X");
  EXPECT_EQ(first["expansions"][0]["expanded_at"]["begin"]["line"], 2);
  EXPECT_EQ(first["expansions"][0]["defined_at"]["begin"]["column"], 9);
}

TEST(RenderJson, NoLocationIsNull) {
  SourceManager sm;
  auto j = nlohmann::json::parse(render_json(Diagnostic::error({}, "e"), sm));
  EXPECT_TRUE(j["range"].is_null());
}

}  // namespace
}  // namespace safegi

namespace safegi {
namespace {

TEST(RenderJson, InvalidUtf8IsReplacedNotThrown) {
  // A file name is data (the editor opens it): its bytes go as they are, and
  // what is not UTF-8 becomes U+FFFD. Message text is escaped (next test).
  SourceManager sm;
  FileId f = sm.add_file("a\x86.glsl", "\x86\n");
  std::string json = render_json(Diagnostic::error(sm.range_of(f, 0, 1), "bad byte '\x86'"), sm);
  EXPECT_NE(json.find("\"file\":\"a\xEF\xBF\xBD.glsl\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"message\":\"bad byte '\\\\x86'\""), std::string::npos) << json;
}

TEST(RenderJson, MessageTextCarriesNoControlCharacters) {
  SourceManager sm;
  FileId f = sm.add_file("a.glsl", "\x1b[2J\n");
  Diagnostic d = Diagnostic::error(sm.range_of(f, 0, 1), "unknown '\x1b[2J'")
                     .with_hint("not \x07")
                     .with_note(Diagnostic::note(sm.range_of(f, 0, 1), "\x9b here"));
  auto j = nlohmann::json::parse(render_json(d, sm));
  EXPECT_EQ(j["message"], "unknown '\\x1B[2J'");
  EXPECT_EQ(j["hint"], "not \\x07");
  EXPECT_EQ(j["notes"][0]["message"], "\\x9B here");
}

}  // namespace
}  // namespace safegi
