#include "safegi/diagnostics/file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace safegi {

std::optional<std::string> read_file(const std::string& path, std::string* error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    if (error) *error = std::strerror(errno);
    return std::nullopt;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) {
    if (error) *error = "read error";
    return std::nullopt;
  }
  return std::move(buffer).str();
}

}  // namespace safegi
