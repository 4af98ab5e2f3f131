// libFuzzer target over safegi-lsp's engine: the input is a byte stream as
// a client would write it, cut into reads of varying size, after a fixed
// initialize handshake so that every handler is reachable. Any crash,
// sanitizer report, hang, or reply that is not one JSON object is a bug.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "safegi/lsp/framing.hpp"
#include "safegi/lsp/server.hpp"

namespace {

void check_reply(const std::string& reply) {
  const nlohmann::json message = nlohmann::json::parse(reply, nullptr, false);
  if (message.is_discarded() || !message.is_object() || message.value("jsonrpc", "") != "2.0") __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  safegi::lsp::ServerOptions options;
  // Only the built-in prelude: the fuzzer never reads the file system.
  options.read_file = [](const std::string&) -> std::optional<std::string> { return std::nullopt; };
  safegi::lsp::Server server(std::move(options));
  // utf-8 or utf-16 positions, with or without related information: the first byte says.
  const unsigned mode = size > 0 ? data[0] : 0;
  nlohmann::json capabilities = nlohmann::json::object();
  if (mode & 1) capabilities["general"]["positionEncodings"] = {"utf-8"};
  if (mode & 2) capabilities["textDocument"]["publishDiagnostics"]["relatedInformation"] = true;
  for (const std::string& reply : server.handle(nlohmann::json{{"jsonrpc", "2.0"}, {"id", 0}, {"method", "initialize"},
                                                              {"params", {{"capabilities", capabilities}}}}.dump()))
    check_reply(reply);

  safegi::lsp::MessageReader reader;
  const std::size_t chunk = 1 + (mode >> 2);  // 1 … 64 bytes per read
  for (std::size_t at = size > 0 ? 1 : 0; at < size && !server.exited(); at += chunk) {
    reader.feed(std::string_view(reinterpret_cast<const char*>(data) + at, std::min(chunk, size - at)));
    while (std::optional<safegi::lsp::Frame> frame = reader.next()) {
      if (!frame->error.empty()) {
        check_reply(safegi::lsp::Server::framing_error(frame->error));
        continue;
      }
      for (const std::string& reply : server.handle(frame->body)) check_reply(reply);
      if (server.exited()) break;
    }
  }
  return 0;
}
