#include "test_client.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <stdexcept>
#include <thread>

#include "uri.hpp"

extern char** environ;

namespace safegi::lsp::testing {

Client::Client(std::vector<std::string> args) {
  int in[2], out[2];
  if (::pipe(in) != 0 || ::pipe(out) != 0) throw std::runtime_error("pipe failed");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
  for (int fd : {in[0], in[1], out[0], out[1]}) posix_spawn_file_actions_addclose(&actions, fd);
  std::vector<std::string> argv_text = {SAFEGI_LSP_EXECUTABLE};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  const int spawned = posix_spawn(&pid_, SAFEGI_LSP_EXECUTABLE, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(in[0]);
  ::close(out[1]);
  to_server_ = in[1];
  from_server_ = out[0];
  if (spawned != 0) throw std::runtime_error("cannot start " + std::string(SAFEGI_LSP_EXECUTABLE));
  ::signal(SIGPIPE, SIG_IGN);  // the tests write to servers that have exited
}

Client::~Client() {
  close_input();
  if (from_server_ >= 0) ::close(from_server_);
  if (!status_ && pid_ > 0) {
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
  }
}

void Client::send_raw(const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(to_server_, bytes.data() + done, bytes.size() - done);
    if (n <= 0) return;  // the server is gone: the test's assertions say so
    done += static_cast<std::size_t>(n);
  }
}

void Client::send(const json& message) { send_raw(frame(message.dump())); }

void Client::notify(const std::string& method, json params) {
  send({{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}});
}

json Client::request(const std::string& method, json params) {
  const int id = next_id_++;
  send({{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", std::move(params)}});
  while (std::optional<json> m = receive()) {
    if (m->contains("id") && (*m)["id"] == id && !m->contains("method")) return *m;
    pending_.push_back(std::move(*m));
  }
  return json{{"error", "no response to " + method}};
}

std::optional<json> Client::receive(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    if (std::optional<Frame> f = reader_.next()) {
      if (!f->error.empty()) return json{{"framing_error", f->error}};
      return json::parse(f->body, nullptr, false);
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return std::nullopt;
    pollfd p{from_server_, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(left.count())) <= 0) continue;
    char buffer[1 << 16];
    const ssize_t n = ::read(from_server_, buffer, sizeof buffer);
    if (n <= 0) return std::nullopt;  // the server closed its output
    reader_.feed(std::string_view(buffer, static_cast<std::size_t>(n)));
  }
}

json Client::notification(const std::string& method) {
  for (auto it = pending_.begin(); it != pending_.end(); ++it)
    if (it->value("method", "") == method) {
      json found = std::move(*it);
      pending_.erase(it);
      return found;
    }
  while (std::optional<json> m = receive()) {
    if (m->value("method", "") == method) return *m;
    pending_.push_back(std::move(*m));
  }
  return json{{"error", "no " + method + " notification"}};
}

void Client::close_input() {
  if (to_server_ >= 0) ::close(to_server_);
  to_server_ = -1;
}

int Client::wait_exit(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!status_) {
    int status = 0;
    const pid_t done = ::waitpid(pid_, &status, WNOHANG);
    if (done == pid_) {
      status_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      break;
    }
    if (std::chrono::steady_clock::now() > deadline) return -1;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return *status_;
}

bool Client::running() {
  if (status_) return false;
  int status = 0;
  if (::waitpid(pid_, &status, WNOHANG) == pid_) {
    status_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return false;
  }
  return true;
}

std::string document_uri(const std::string& name) { return uri_from_path("/tmp/safegi-lsp-test/" + name); }

}  // namespace safegi::lsp::testing
