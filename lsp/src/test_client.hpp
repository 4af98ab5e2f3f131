#pragma once
// A JSON-RPC client for the tests, talking to the safegi-lsp process over
// pipes as an editor does: it frames what it sends, reads frames back (with a
// deadline, so a server that stops answering fails the test instead of
// hanging it) and keeps the notifications that arrive between responses.

#include <sys/types.h>

#include <chrono>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "safegi/lsp/framing.hpp"

namespace safegi::lsp::testing {

using json = nlohmann::json;

class Client {
 public:
  explicit Client(std::vector<std::string> args = {});
  ~Client();  // closes the pipes, kills the server if it still runs

  void send_raw(const std::string& bytes);
  void send(const json& message);
  json request(const std::string& method, json params);  // sends, then waits for the response with its id
  void notify(const std::string& method, json params);
  // The next message from the server, or nothing before the deadline / at end of output.
  std::optional<json> receive(std::chrono::milliseconds timeout = std::chrono::seconds(20));
  // The next notification `method` (earlier notifications of other methods are kept).
  json notification(const std::string& method);

  void close_input();
  // Waits for the server to end; its exit status, or -1 when it did not end or was killed by a signal.
  int wait_exit(std::chrono::milliseconds timeout = std::chrono::seconds(20));
  bool running();

 private:
  pid_t pid_ = -1;
  int to_server_ = -1, from_server_ = -1;
  MessageReader reader_;
  std::deque<json> pending_;  // notifications read while waiting for a response
  int next_id_ = 1;
  std::optional<int> status_;
};

// A file:// URI for a made-up path in a directory that exists.
std::string document_uri(const std::string& name);

}  // namespace safegi::lsp::testing
