#pragma once
// Reading a whole file, the one way the compiler's parts do it (the source manager, the
// preprocessor's #include, compile()'s default reader, safeglslc, the language server).

#include <optional>
#include <string>

namespace safegi {

// The bytes of the file at `path`, as they are (binary: no newline translation), or
// nullopt when it cannot be opened or read; then `error`, if given, says why
// (strerror's text, or "read error").
std::optional<std::string> read_file(const std::string& path, std::string* error = nullptr);

}  // namespace safegi
