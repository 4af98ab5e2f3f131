#pragma once
// safegi-lsp's protocol engine: JSON-RPC messages in, messages out, no I/O of
// its own (main.cpp moves the bytes; tests and the fuzzer call it directly).
//
//   safegi::lsp::Server server(options);
//   for (const std::string& reply : server.handle(body)) send(frame(reply));
//   if (server.exited()) return server.exit_code();
//
// Every message gets what the protocol says: a request its response or a
// JSON-RPC error (-32700 unparsable, -32600 not a request, -32601 unknown
// method, -32602 bad parameters, -32002 before initialize), a notification
// nothing (problems with one are reported by window/logMessage). No input
// makes it throw or crash. See docs/editor.md.

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace safegi::lsp {

inline constexpr std::string_view kServerName = "safegi-lsp";

struct ServerOptions {
  // As safeglslc's -I, -D and --strict; initializationOptions may add to them.
  std::vector<std::string> include_paths;
  std::vector<std::pair<std::string, std::string>> defines;
  bool strict = false;
  // A file with the built-in prelude's text, where go to definition shows its
  // declarations; used only when its text is the built-in one ("": none).
  std::string prelude_file;
  // Reads `#include`d files that are not open in the editor; default: the disk.
  std::function<std::optional<std::string>(const std::string& path)> read_file;
};

class Server {
 public:
  explicit Server(ServerOptions options = {});
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // One message body; the messages to send, in order (responses, diagnostics).
  std::vector<std::string> handle(std::string_view body);
  // The error response for a frame the reader could not read.
  static std::string framing_error(std::string_view reason);

  bool exited() const;  // the exit notification came
  // 0 when shutdown came before exit, else 1 (also for a connection that just closes).
  int exit_code() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The installed or in-tree copy of the prelude next to `executable`
// (../share/safegi/include/safegi/prelude.sgl), if its text is the built-in one.
std::string find_prelude_file(const std::string& executable);

}  // namespace safegi::lsp
