#pragma once
// The server in-process for the tests: JSON in, parsed replies out.

#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "safegi/lsp/server.hpp"

namespace safegi::lsp::testing {

using json = nlohmann::json;

class InProcess {
 public:
  explicit InProcess(ServerOptions options = {}) : server_(std::move(options)) {}
  std::vector<json> raw(const std::string& body) {
    std::vector<json> out;
    for (const std::string& m : server_.handle(body)) out.push_back(json::parse(m));
    return out;
  }
  std::vector<json> send(const json& message) { return raw(message.dump()); }
  json request(const std::string& method, json params = json::object()) {
    const std::vector<json> replies = send({{"jsonrpc", "2.0"}, {"id", ++id_}, {"method", method}, {"params", params}});
    EXPECT_EQ(replies.size(), 1u) << method;
    return replies.empty() ? json() : replies.back();
  }
  std::vector<json> notify(const std::string& method, json params = json::object()) {
    return send({{"jsonrpc", "2.0"}, {"method", method}, {"params", params}});
  }
  json initialize(json capabilities = json::object(), json options = nullptr) {
    json params{{"capabilities", capabilities}, {"rootUri", "file:///tmp"}};
    if (!options.is_null()) params["initializationOptions"] = options;
    json r = request("initialize", params);
    notify("initialized");
    return r;
  }
  // didOpen; the diagnostics published for it.
  json open(const std::string& uri, const std::string& text) {
    const std::vector<json> out =
        notify("textDocument/didOpen", {{"textDocument", {{"uri", uri}, {"languageId", "glsl"}, {"version", 1}, {"text", text}}}});
    return out.empty() ? json() : out.front()["params"];
  }
  Server& server() { return server_; }

 private:
  Server server_;
  int id_ = 0;
};

inline ServerOptions in_memory(std::map<std::string, std::string> files) {
  ServerOptions o;
  o.read_file = [files](const std::string& path) -> std::optional<std::string> {
    auto it = files.find(path);
    if (it == files.end()) return std::nullopt;
    return it->second;
  };
  return o;
}


// A uri + position params object.
inline nlohmann::json at(const std::string& uri, int line, int character) {
  return {{"textDocument", {{"uri", uri}}}, {"position", {{"line", line}, {"character", character}}}};
}

}  // namespace safegi::lsp::testing
