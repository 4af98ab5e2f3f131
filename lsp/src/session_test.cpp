// The safegi-lsp program driven as an editor drives it: a JSON-RPC client on
// pipes (test_client.hpp) through a whole session, malformed bytes that must
// get errors and never end the process, and the exit codes of the spec.
#include <gtest/gtest.h>

#include <safegi/diagnostics/file.hpp>

#include "test_client.hpp"

namespace safegi::lsp::testing {
namespace {

std::string example(const std::string& name) {
  return read_file(std::string(SAFEGI_EXAMPLE_SHADERS) + "/" + name).value_or("");
}

json position(int line, int character) { return {{"line", line}, {"character", character}}; }

TEST(Session, AnEditorSessionFromInitializeToExit) {
  Client client({"--prelude-file", SAFEGI_SOURCE_PRELUDE});
  const json init = client.request("initialize", {{"processId", nullptr}, {"rootUri", nullptr},
                                                  {"capabilities", {{"textDocument", {{"publishDiagnostics", {{"relatedInformation", true}}}}}}}});
  ASSERT_TRUE(init.contains("result")) << init.dump();
  EXPECT_EQ(init["result"]["capabilities"]["hoverProvider"], true);
  client.notify("initialized", json::object());

  // The example shader with its cosine forgotten.
  const std::string uri = document_uri("point_light.sgl.frag");
  std::string text = example("point_light.sgl.frag");
  const std::string cosine = " * cosTheta";
  const std::size_t at = text.find(cosine);
  ASSERT_NE(at, std::string::npos);
  text.erase(at, cosine.size());
  client.notify("textDocument/didOpen", {{"textDocument", {{"uri", uri}, {"languageId", "glsl"}, {"version", 1}, {"text", text}}}});
  json published = client.notification("textDocument/publishDiagnostics");
  ASSERT_EQ(published["params"]["diagnostics"].size(), 1u) << published.dump(1);
  const json& d = published["params"]["diagnostics"][0];
  EXPECT_EQ(d["code"], "E-DIMENSION-MISMATCH");
  EXPECT_EQ(d["range"]["start"], position(24, 27));
  EXPECT_EQ(d["relatedInformation"][1]["message"], "help: the value lacks a factor of proj: missing cosine factor, e.g. max(dot(n, wi), 0.0)?");

  // Put the cosine back where it was: line 25, after `lightI`.
  client.notify("textDocument/didChange",
                {{"textDocument", {{"uri", uri}, {"version", 2}}},
                 {"contentChanges", {{{"range", {{"start", position(24, 38)}, {"end", position(24, 38)}}}, {"text", cosine}}}}});
  published = client.notification("textDocument/publishDiagnostics");
  EXPECT_EQ(published["params"]["version"], 2);
  EXPECT_EQ(published["params"]["diagnostics"], json::array());

  const json hover = client.request("textDocument/hover", {{"textDocument", {{"uri", uri}}}, {"position", position(24, 23)}});
  EXPECT_EQ(hover["result"]["contents"]["value"],
            "```glsl\nspectrum<radiance> L\n```\nspectrum<radiance> — W·m⁻²·sr⁻¹\n\nradiance = energy·length⁻²·time⁻¹·solid_angle⁻¹·proj⁻¹; "
            "the SI units leave out proj, the projected-cosine factor (a pure number in SI)");
  const json definition = client.request("textDocument/definition", {{"textDocument", {{"uri", uri}}}, {"position", position(24, 43)}});
  EXPECT_EQ(definition["result"], json::parse(R"({"uri": ")" + uri + R"(",
      "range": {"start": {"line": 20, "character": 16}, "end": {"line": 20, "character": 24}}})"));  // cosTheta
  const json completion = client.request("textDocument/completion", {{"textDocument", {{"uri", uri}}}, {"position", position(7, 14)}});
  ASSERT_TRUE(completion["result"].contains("items")) << completion.dump();
  EXPECT_EQ(completion["result"]["items"][0]["label"], "world");  // `point<` on line 8

  EXPECT_EQ(client.request("shutdown", nullptr)["result"], nullptr);
  client.notify("exit", nullptr);
  EXPECT_EQ(client.wait_exit(), 0);
}

TEST(Session, MalformedBytesGetErrorsAndTheServerKeepsServing) {
  Client client;
  const std::pair<std::string, int> cases[] = {
      {frame("{not json"), -32700},
      // A frame without a length; after it the reader looks for the next
      // Content-Length header (so a second header block without one would be
      // skipped with what follows it, never misread).
      {"Content-Type: application/json\r\n\r\n{}", -32700},
      {"Content-Length: -4\r\n\r\n", -32700},
      {"Content-Length: 99999999999999999999\r\n\r\n", -32700},
      {frame("[]"), -32600},
      {frame(R"({"jsonrpc":"2.0","id":1,"method":"textDocument/hover"})"), -32002},
  };
  for (const auto& [bytes, code] : cases) {
    client.send_raw(bytes);
    const std::optional<json> reply = client.receive();
    ASSERT_TRUE(reply) << bytes;
    EXPECT_EQ((*reply)["error"]["code"], code) << bytes << " -> " << reply->dump();
  }
  // Notifications, well-formed or not, are never answered; the next request is.
  client.notify("initialized", json::object());
  client.send_raw(frame(R"({"jsonrpc":"2.0","method":"$/x","params":1})"));
  const json init = client.request("initialize", {{"capabilities", json::object()}});
  EXPECT_EQ(init["id"], 1);
  EXPECT_TRUE(init.contains("result")) << init.dump();
  EXPECT_TRUE(client.running());
}

TEST(Session, SplitAndBatchedWrites) {
  Client client;
  const std::string init = frame(R"({"jsonrpc":"2.0","id":7,"method":"initialize","params":{"capabilities":{}}})");
  for (char c : init) client.send_raw(std::string(1, c));  // one byte per write
  std::optional<json> reply = client.receive();
  ASSERT_TRUE(reply);
  EXPECT_EQ((*reply)["id"], 7);
  // Two requests in one write, answered in order.
  client.send_raw(frame(R"({"jsonrpc":"2.0","id":8,"method":"nope"})") + frame(R"({"jsonrpc":"2.0","id":9,"method":"shutdown"})"));
  reply = client.receive();
  ASSERT_TRUE(reply);
  EXPECT_EQ((*reply)["id"], 8);
  EXPECT_EQ((*reply)["error"]["code"], -32601);
  reply = client.receive();
  ASSERT_TRUE(reply);
  EXPECT_EQ((*reply)["id"], 9);
  EXPECT_EQ((*reply)["result"], nullptr);
  client.notify("exit", nullptr);
  EXPECT_EQ(client.wait_exit(), 0);
}

TEST(Session, ExitWithoutShutdownAndAClosedConnectionAreErrors) {
  {
    Client client;
    client.request("initialize", {{"capabilities", json::object()}});
    client.notify("exit", nullptr);
    EXPECT_EQ(client.wait_exit(), 1);
  }
  {
    Client client;
    client.request("initialize", {{"capabilities", json::object()}});
    client.send_raw("Content-Length: 100\r\n\r\n{\"jsonrpc\"");  // cut short by the end of the connection
    client.close_input();
    EXPECT_EQ(client.wait_exit(), 1);
  }
}

TEST(Session, TheCommandLine) {
  Client version({"--version"});
  EXPECT_EQ(version.wait_exit(), 0);
  Client unknown({"--no-such-flag"});
  EXPECT_EQ(unknown.wait_exit(), 2);  // a usage error, as every SafeGI program's (not CLI11's 109)
}

}  // namespace
}  // namespace safegi::lsp::testing
