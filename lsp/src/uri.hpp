#pragma once
// file:// URIs (RFC 8089) and the paths they name. Editors percent-encode
// everything but unreserved characters and '/', so the round trip compares
// paths, never URI spellings.

#include <optional>
#include <string>
#include <string_view>

namespace safegi::lsp {

// The path of a `file:` URI (`file:///a/b%20c.frag` -> `/a/b c.frag`;
// `file://localhost/a` too); nothing for another scheme or a bad escape.
std::optional<std::string> path_from_uri(std::string_view uri);
// `file://` + the absolute path, percent-encoded.
std::string uri_from_path(std::string_view path);

}  // namespace safegi::lsp
