// safegi-lsp: the SafeGI language server, over stdin/stdout (docs/editor.md).
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>
#include <safegi/diagnostics/command_line.hpp>

#include "safegi/lsp/framing.hpp"
#include "safegi/lsp/server.hpp"

namespace {

bool write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

std::string executable_path(const char* argv0) {
  char buffer[PATH_MAX];
  const ssize_t n = ::readlink("/proc/self/exe", buffer, sizeof buffer - 1);
  return n > 0 ? std::string(buffer, static_cast<std::size_t>(n)) : std::string(argv0);
}

int serve(int argc, char** argv) {
  CLI::App app{"safegi-lsp: language server for SafeGI annotated GLSL (LSP over stdin/stdout)", "safegi-lsp"};
  safegi::lsp::ServerOptions options;
  std::vector<std::string> defines;
  bool stdio = true;
  app.add_flag("--stdio", stdio, "talk LSP over stdin/stdout (the default and only transport)");
  app.add_option("-I", options.include_paths, "#include search directory, as safeglslc -I");
  app.add_option("-D", defines, "define a macro NAME[=value], as safeglslc -D");
  app.add_flag("--strict", options.strict, "warn about unannotated interface variables, as safeglslc --strict");
  app.add_option("--prelude-file", options.prelude_file,
                 "a copy of safegi/prelude.sgl where go to definition shows the prelude (default: the installed one)");
  app.set_version_flag("--version", std::string(safegi::lsp::kServerName) + " 0.1.0");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return safegi::exit_after_parse_error(app, error);
  }
  for (const std::string& d : defines) {
    const std::size_t eq = d.find('=');
    options.defines.emplace_back(d.substr(0, eq), eq == std::string::npos ? "1" : d.substr(eq + 1));
  }
  if (options.prelude_file.empty()) options.prelude_file = safegi::lsp::find_prelude_file(executable_path(argv[0]));

  ::signal(SIGPIPE, SIG_IGN);  // a client that goes away ends the loop through write(), not a signal
  safegi::lsp::Server server(std::move(options));
  safegi::lsp::MessageReader reader;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(STDIN_FILENO, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // the client closed the connection without exit
    reader.feed(std::string_view(buffer, static_cast<std::size_t>(n)));
    while (std::optional<safegi::lsp::Frame> frame = reader.next()) {
      std::vector<std::string> replies =
          frame->error.empty() ? server.handle(frame->body) : std::vector<std::string>{safegi::lsp::Server::framing_error(frame->error)};
      for (const std::string& reply : replies)
        if (!write_all(STDOUT_FILENO, safegi::lsp::frame(reply))) return 1;
      if (server.exited()) return server.exit_code();
    }
  }
  return server.exit_code();
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return serve(argc, argv);
  } catch (const std::bad_alloc&) {
    // Said on stderr, which clients show in their log: stdout is the protocol's.
    std::cerr << "safegi-lsp: " << safegi::error_report(safegi::out_of_memory_text("serving"));
    return safegi::kExitInputError;
  }
}
