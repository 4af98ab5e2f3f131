// The protocol engine in-process: lifecycle and JSON-RPC errors, diagnostics
// (ranges, severities, codes, related information, include chains),
// document sync (full and incremental) and position encodings.
#include <gtest/gtest.h>

#include "in_process.hpp"

namespace safegi::lsp {
namespace {

using testing::InProcess;
using testing::json;
using testing::in_memory;

const char* kShader = R"(#version 330 core
#include <safegi/prelude.sgl>
space world;
uniform spectrum<intensity> I;
in point<world> P;
out vec4 color;
void main() {
    float<length> d = length(P - P);
    /* Φ→😀 */ spectrum<irradiance> E = I / (d * d);
    color = vec4(E, 1.0);
}
)";

// -------------------------------------------------------------- lifecycle

TEST(Server, RequestsBeforeInitializeAreRefusedNotificationsIgnored) {
  InProcess s;
  const json r = s.request("textDocument/hover", {{"textDocument", {{"uri", "file:///a.frag"}}}, {"position", {{"line", 0}, {"character", 0}}}});
  EXPECT_EQ(r["error"]["code"], -32002);
  EXPECT_EQ(r["id"], 1);
  EXPECT_TRUE(s.notify("textDocument/didOpen", {{"textDocument", {{"uri", "file:///a.frag"}, {"text", ""}}}}).empty());
  EXPECT_TRUE(s.raw(R"({"jsonrpc":"2.0","method":"textDocument/didOpen","params":7})").empty());  // not even a log message
  EXPECT_FALSE(s.server().exited());
}

TEST(Server, InitializeSaysWhatTheServerDoes) {
  InProcess s;
  const json r = s.initialize();
  EXPECT_EQ(r["result"]["capabilities"], json::parse(R"j({
    "positionEncoding": "utf-16",
    "textDocumentSync": {"openClose": true, "change": 2},
    "hoverProvider": true, "definitionProvider": true,
    "completionProvider": {"triggerCharacters": ["<", ","]}})j"));
  EXPECT_EQ(r["result"]["serverInfo"]["name"], "safegi-lsp");
  EXPECT_EQ(s.request("initialize", {{"capabilities", json::object()}})["error"]["code"], -32600);  // only once
}

TEST(Server, Utf8IsChosenWhenTheClientOffersIt) {
  InProcess s;
  const json r = s.initialize({{"general", {{"positionEncodings", {"utf-16", "utf-8"}}}}});
  EXPECT_EQ(r["result"]["capabilities"]["positionEncoding"], "utf-8");
}

TEST(Server, ShutdownThenExitIsZeroExitAloneIsOne) {
  {
    InProcess s;
    s.initialize();
    EXPECT_EQ(s.request("shutdown")["result"], nullptr);
    EXPECT_EQ(s.request("textDocument/hover", json::object())["error"]["code"], -32600);  // shutting down
    EXPECT_TRUE(s.notify("exit").empty());
    EXPECT_TRUE(s.server().exited());
    EXPECT_EQ(s.server().exit_code(), 0);
    EXPECT_TRUE(s.raw(R"({"jsonrpc":"2.0","id":9,"method":"shutdown"})").empty());  // after exit: nothing
  }
  {
    InProcess s;
    s.initialize();
    s.notify("exit");
    EXPECT_TRUE(s.server().exited());
    EXPECT_EQ(s.server().exit_code(), 1);
  }
  {
    InProcess s;  // exit before initialize ends the server too
    s.notify("exit");
    EXPECT_TRUE(s.server().exited());
    EXPECT_EQ(s.server().exit_code(), 1);
  }
}

// --------------------------------------------------------- JSON-RPC errors

TEST(Server, MalformedMessagesGetJsonRpcErrors) {
  InProcess s;
  s.initialize();
  const std::pair<std::string, int> cases[] = {
      {"{not json", -32700},
      {"", -32700},
      {"[1, 2]", -32600},                                                 // a batch
      {"42", -32600},
      {R"({"id": 1, "method": "shutdown"})", -32600},                     // no jsonrpc
      {R"({"jsonrpc": "1.0", "id": 1, "method": "shutdown"})", -32600},
      {R"({"jsonrpc": "2.0", "id": 1})", -32600},                         // no method
      {R"({"jsonrpc": "2.0", "id": 1, "method": 7})", -32600},
      {R"({"jsonrpc": "2.0", "id": {"x": 1}, "method": "shutdown"})", -32600},
      {R"({"jsonrpc": "2.0", "id": 1.5, "method": "shutdown"})", -32600},
      {R"({"jsonrpc": "2.0", "id": 1, "method": "shutdown", "params": 3})", -32600},
      {R"({"jsonrpc": "2.0", "id": 1, "method": "textDocument/rename", "params": {}})", -32601},
      {R"({"jsonrpc": "2.0", "id": "s", "method": "$/unknown"})", -32601},
      {R"({"jsonrpc": "2.0", "id": 1, "method": "textDocument/hover", "params": {}})", -32602},
      {R"({"jsonrpc": "2.0", "id": 1, "method": "textDocument/hover", "params": [1]})", -32602},
      {R"({"jsonrpc": "2.0", "id": 1, "method": "textDocument/hover",
           "params": {"textDocument": {"uri": "file:///not-open.frag"}, "position": {"line": 0, "character": 0}}})", -32602},
  };
  for (const auto& [body, code] : cases) {
    const std::vector<json> replies = s.raw(body);
    ASSERT_EQ(replies.size(), 1u) << body;
    EXPECT_EQ(replies[0]["error"]["code"], code) << body << " -> " << replies[0].dump();
    EXPECT_EQ(replies[0]["jsonrpc"], "2.0");
  }
  // The id is echoed when it is one; a string id stays a string.
  EXPECT_EQ(s.raw(R"({"jsonrpc": "2.0", "id": "abc", "method": "nope"})")[0]["id"], "abc");
  EXPECT_EQ(s.raw(R"({"jsonrpc": "2.0", "id": null, "method": "nope"})")[0]["id"], nullptr);
  EXPECT_FALSE(s.server().exited());
}

TEST(Server, DeeplyNestedJsonIsNeverCopied) {
  // json::parse is iterative and its destructor too, but copying a value
  // recurses (a copy overflows an 8 MB stack from about 60 000 levels in a
  // Release build): 100 000 levels of nesting anywhere in a message must not
  // reach a copy (the server's first version crashed on this).
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  InProcess s;
  EXPECT_EQ(s.raw(R"({"jsonrpc":"2.0","id":1,"method":"initialize","params":{"capabilities":)" + deep + "}}")[0]["result"]
                ["capabilities"]["positionEncoding"],
            "utf-16");
  for (const std::string& body : {R"({"jsonrpc":"2.0","id":)" + deep + R"(,"method":"x"})",
                                  R"({"jsonrpc":)" + deep + R"(,"id":2,"method":"x"})",
                                  R"({"jsonrpc":"2.0","id":3,"method":)" + deep + "}",
                                  R"({"jsonrpc":"2.0","id":4,"method":"x","params":)" + deep + "}",
                                  R"({"jsonrpc":"2.0","method":"textDocument/didOpen","params":{"textDocument":)" + deep + "}}"})
    EXPECT_LE(s.raw(body).size(), 1u);
  EXPECT_EQ(s.raw(R"({"jsonrpc":"2.0","id":5,"method":"textDocument/hover","params":{"textDocument":{"uri":)" + deep +
                  R"(},"position":{"line":0,"character":0}}})")[0]["error"]["code"],
            -32602);
}

TEST(Server, NotificationsAreNeverAnswered) {
  InProcess s;
  s.initialize();
  EXPECT_TRUE(s.notify("$/cancelRequest", {{"id", 1}}).empty());
  EXPECT_TRUE(s.notify("workspace/unknownThing").empty());
  EXPECT_TRUE(s.raw(R"({"jsonrpc":"2.0","id":5,"result":null})").empty());  // a client's reply
  // A broken notification: a log message, never a response.
  const std::vector<json> out = s.notify("textDocument/didOpen", {{"textDocument", {{"uri", 3}}}});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0]["method"], "window/logMessage");
  EXPECT_FALSE(out[0].contains("id"));
  EXPECT_EQ(out[0]["params"]["message"], "safegi-lsp: textDocument/didOpen: 'uri' must be a string");
}

TEST(Server, BadInitializationOptionsAreInvalidParams) {
  InProcess s;
  EXPECT_EQ(s.request("initialize", {{"initializationOptions", {{"includePaths", "inc"}}}})["error"]["code"], -32602);
  EXPECT_EQ(s.request("initialize", {{"initializationOptions", {{"strict", 1}}}})["error"]["code"], -32602);
  EXPECT_EQ(s.request("initialize", {{"initializationOptions", {{"notesInMessage", "yes"}}}})["error"]["code"], -32602);
  EXPECT_TRUE(s.request("initialize", {{"initializationOptions", {{"strict", true}}}}).contains("result"));
}

TEST(Server, NotesInMessageWhenAskedEvenIfTheClientTakesRelatedInformation) {
  InProcess s;
  s.initialize({{"textDocument", {{"publishDiagnostics", {{"relatedInformation", true}}}}}}, {{"notesInMessage", true}});
  const json d = s.open("file:///tmp/a.sgl.frag", kShader)["diagnostics"][0];
  EXPECT_FALSE(d.contains("relatedInformation"));
  EXPECT_NE(d["message"].get<std::string>().find("\n/tmp/a.sgl.frag:9:42: note: 'E' declared here\nhelp: "), std::string::npos);
}

// ------------------------------------------------------------ diagnostics

TEST(Server, DiagnosticsHaveRangeSeverityCodeAndRelatedInformation) {
  InProcess s;
  s.initialize({{"textDocument", {{"publishDiagnostics", {{"relatedInformation", true}}}}}});
  const json published = s.open("file:///tmp/a.sgl.frag", kShader);
  EXPECT_EQ(published["uri"], "file:///tmp/a.sgl.frag");
  EXPECT_EQ(published["version"], 1);
  ASSERT_EQ(published["diagnostics"].size(), 1u) << published.dump(1);
  // Line 9 is `    /* Φ→😀 */ spectrum<irradiance> E = I / (d * d);`: the initialiser
  // starts at UTF-16 column 40 (byte 45: Φ is 2 bytes, → 3, 😀 4 and 2 UTF-16 units).
  EXPECT_EQ(published["diagnostics"][0], json::parse(R"j({
    "range": {"start": {"line": 8, "character": 40}, "end": {"line": 8, "character": 51}},
    "severity": 1, "source": "safeglslc", "code": "E-DIMENSION-MISMATCH",
    "message": "cannot initialize 'E' of type spectrum<irradiance> with a value of type spectrum<energy·length⁻²·time⁻¹·solid_angle⁻¹>",
    "relatedInformation": [
      {"location": {"uri": "file:///tmp/a.sgl.frag", "range": {"start": {"line": 8, "character": 36}, "end": {"line": 8, "character": 37}}},
       "message": "'E' declared here"},
      {"location": {"uri": "file:///tmp/a.sgl.frag", "range": {"start": {"line": 8, "character": 40}, "end": {"line": 8, "character": 51}}},
       "message": "help: the value lacks a factor of proj: missing cosine factor, e.g. max(dot(n, wi), 0.0)?"}]})j"))
      << published.dump(1);
}

TEST(Server, WithoutRelatedInformationNotesJoinTheMessageAsSafeglslcPrintsThem) {
  InProcess s;
  s.initialize();
  const json published = s.open("file:///tmp/a.sgl.frag", kShader);
  ASSERT_EQ(published["diagnostics"].size(), 1u);
  EXPECT_FALSE(published["diagnostics"][0].contains("relatedInformation"));
  EXPECT_EQ(published["diagnostics"][0]["message"],
            "cannot initialize 'E' of type spectrum<irradiance> with a value of type spectrum<energy·length⁻²·time⁻¹·solid_angle⁻¹>\n"
            "/tmp/a.sgl.frag:9:42: note: 'E' declared here\n"
            "help: the value lacks a factor of proj: missing cosine factor, e.g. max(dot(n, wi), 0.0)?");
}

TEST(Server, ControlBytesOfTheSourceAreEscapedInMessages) {
  // An editor renders the message: ESC, BEL or CSI from the file must arrive as text.
  InProcess s;
  s.initialize();
  const json d = s.open("file:///tmp/e.sgl.frag", "#version 330\n#error \x1b]0;owned\x07 \xc2\x9b\nvoid main() {}\n")["diagnostics"][0];
  EXPECT_EQ(d["message"], "#error: \\x1B]0;owned\\x07 \\xC2\\x9B");
}

TEST(Server, Utf8PositionsAreByteColumns) {
  InProcess s;
  s.initialize({{"general", {{"positionEncodings", {"utf-8"}}}}});
  const json d = s.open("file:///tmp/a.sgl.frag", kShader)["diagnostics"][0];
  EXPECT_EQ(d["range"]["start"], json::parse(R"j({"line": 8, "character": 45})j"));
}

TEST(Server, ADiagnosticInAnIncludedFileIsReportedAtTheIncludeLine) {
  ServerOptions options = in_memory({{"/tmp/inc/common.glsl", "// a header\nfloat<lenght> half_of(float<length> x) { return x / 2.0; }\n"}});
  InProcess s(std::move(options));
  s.initialize({{"textDocument", {{"publishDiagnostics", {{"relatedInformation", true}}}}}});
  const json published = s.open("file:///tmp/inc/main.sgl.frag",
                                "#version 330 core\n#include <safegi/prelude.sgl>\n#include \"common.glsl\"\nvoid main() {}\n");
  ASSERT_EQ(published["diagnostics"].size(), 1u) << published.dump(1);
  const json& d = published["diagnostics"][0];
  EXPECT_EQ(d["message"], "In included file: unknown dimension 'lenght'");
  EXPECT_EQ(d["range"]["start"], json::parse(R"j({"line": 2, "character": 0})j"));
  EXPECT_EQ(d["relatedInformation"][0], json::parse(R"j({"location": {"uri": "file:///tmp/inc/common.glsl",
      "range": {"start": {"line": 1, "character": 6}, "end": {"line": 1, "character": 12}}},
      "message": "unknown dimension 'lenght'"})j"));
}

TEST(Server, IncludePathsFromTheWorkspaceRootAndDefinesFromInitializationOptions) {
  InProcess s(in_memory({{"/tmp/shaders/include/units.glsl", "#define LIGHT_DIM intensity\n"}}));
  s.initialize(json::object(), {{"includePaths", {"shaders/include"}}, {"defines", {"USE_UNITS", "SCALE=2.0"}}});  // rootUri file:///tmp
  const json published = s.open("file:///tmp/elsewhere/a.sgl.frag",
      "#include <safegi/prelude.sgl>\n#ifdef USE_UNITS\n#include <units.glsl>\n#endif\n"
      "uniform spectrum<LIGHT_DIM> I;\nvoid main() { float<1> k = SCALE; }\n");
  EXPECT_EQ(published["diagnostics"], json::array()) << published.dump(1);
}

TEST(Server, AnOpenHeaderIsReadAsTheEditorHasItAndItsIncludersFollowItsEdits) {
  InProcess s(in_memory({}));  // nothing on "disk"
  s.initialize();
  EXPECT_EQ(s.open("file:///tmp/h/common.glsl", "float<length> twice(float<length> x) { return 2.0 * x; }\n")["uri"],
            "file:///tmp/h/common.glsl");  // a header alone: no stage, one error of its own
  const json main = s.open("file:///tmp/h/main.sgl.frag",
                           "#include <safegi/prelude.sgl>\n#include \"common.glsl\"\nvoid main() { float<length> y = twice(1.0 * meter); }\n");
  EXPECT_EQ(main["diagnostics"], json::array()) << main.dump(1);
  // Breaking the header republishes the shader that includes it.
  const std::vector<json> out = s.notify("textDocument/didChange",
      {{"textDocument", {{"uri", "file:///tmp/h/common.glsl"}, {"version", 2}}},
       {"contentChanges", {{{"text", "float<time> twice(float<length> x) { return 2.0 * x; }\n"}}}}});
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[1]["params"]["uri"], "file:///tmp/h/main.sgl.frag");
  EXPECT_EQ(out[1]["params"]["diagnostics"].size(), 2u) << out[1].dump(1);  // the header's return, the shader's initialisation
}

// ------------------------------------------------------------- doc sync

TEST(Server, IncrementalChangesInUtf16OnANonAsciiLine) {
  InProcess s;
  s.initialize();
  ASSERT_EQ(s.open("file:///tmp/a.sgl.frag", kShader)["diagnostics"].size(), 1u);
  // Replace `irradiance` (UTF-16 columns 24..34 of line 9) by `intensity`,
  // then ` / (d * d)` (40..50 after the first edit): the shader is then correct.
  const std::vector<json> out = s.notify("textDocument/didChange",
      {{"textDocument", {{"uri", "file:///tmp/a.sgl.frag"}, {"version", 2}}},
       {"contentChanges", {{{"range", {{"start", {{"line", 8}, {"character", 24}}}, {"end", {{"line", 8}, {"character", 34}}}}},
                            {"text", "intensity"}},
                           {{"range", {{"start", {{"line", 8}, {"character", 40}}}, {"end", {{"line", 8}, {"character", 50}}}}},
                            {"text", ""}}}}});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0]["params"]["version"], 2);
  EXPECT_EQ(out[0]["params"]["diagnostics"], json::array()) << out[0].dump(1);
  // The text is what the edits made: hover on `E` says its new type.
  const json h = s.request("textDocument/hover", {{"textDocument", {{"uri", "file:///tmp/a.sgl.frag"}}},
                                                  {"position", {{"line", 8}, {"character", 35}}}});
  EXPECT_EQ(h["result"]["contents"]["value"], "```glsl\nspectrum<intensity> E\n```\nspectrum<intensity> — W·sr⁻¹\n\nintensity = energy·time⁻¹·solid_angle⁻¹");
}

TEST(Server, FullSyncAndAMalformedChangeLeavesTheTextAsItWas) {
  InProcess s;
  s.initialize();
  s.open("file:///tmp/a.sgl.frag", kShader);
  std::vector<json> out = s.notify("textDocument/didChange",
      {{"textDocument", {{"uri", "file:///tmp/a.sgl.frag"}, {"version", 2}}},
       {"contentChanges", {{{"text", "void main() {}\n"}}, {{"range", {{"start", {{"line", 0}}}}}, {"text", "x"}}}}});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0]["method"], "window/logMessage");  // the second change has no character
  out = s.notify("textDocument/didChange", {{"textDocument", {{"uri", "file:///tmp/a.sgl.frag"}, {"version", 3}}},
                                            {"contentChanges", {{{"text", "void main() {}\n"}}}}});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0]["params"]["diagnostics"], json::array());
  out = s.notify("textDocument/didClose", {{"textDocument", {{"uri", "file:///tmp/a.sgl.frag"}}}});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0]["params"]["diagnostics"], json::array());  // cleared
}

TEST(Server, AnUnsavedBufferTakesItsStageFromTheLanguageId) {
  InProcess s;
  s.initialize();
  std::vector<json> out = s.notify("textDocument/didOpen",
      {{"textDocument", {{"uri", "untitled:Untitled-1"}, {"languageId", "frag"}, {"version", 1}, {"text", "void main() { discard; }\n"}}}});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0]["params"]["diagnostics"], json::array());
  out = s.notify("textDocument/didOpen",
      {{"textDocument", {{"uri", "untitled:Untitled-2"}, {"languageId", "glsl"}, {"version", 1}, {"text", "void main() {}\n"}}}});
  EXPECT_EQ(out[0]["params"]["diagnostics"][0]["message"],
            "cannot tell the shader stage of 'untitled:Untitled-2' from its name\n"
            "help: name it *.vert, *.frag, … (or *.sgl.frag), or give the stage with -S");
}

}  // namespace
}  // namespace safegi::lsp
