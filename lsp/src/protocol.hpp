#pragma once
// JSON-RPC 2.0 messages and the LSP structures the server reads and writes.

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "positions.hpp"

namespace safegi::lsp {

using json = nlohmann::json;

// JSON-RPC 2.0 and LSP error codes.
namespace error_code {
inline constexpr int parse_error = -32700;
inline constexpr int invalid_request = -32600;
inline constexpr int method_not_found = -32601;
inline constexpr int invalid_params = -32602;
inline constexpr int internal_error = -32603;
inline constexpr int server_not_initialized = -32002;
inline constexpr int request_failed = -32803;
}  // namespace error_code

// Thrown by a handler for a request it cannot answer; becomes the error response.
struct RequestError {
  int code = error_code::invalid_params;
  std::string message;
};

json response(const json& id, json result);
json error_response(const json& id, int code, const std::string& message);
json notification(const std::string& method, json params);
// Compact text, invalid UTF-8 replaced (a response is never lost to a stray byte).
std::string serialize(const json& message);

// Parameters, checked: a missing or mistyped member is a RequestError (invalid params).
const json& member(const json& object, const char* name);
std::string string_member(const json& object, const char* name);
Position position_from_json(const json& value);
json position_json(Position position);
json range_json(Position begin, Position end);

// LSP enumerations the server uses.
namespace severity {
inline constexpr int error = 1, warning = 2, information = 3, hint = 4;
}
namespace completion_kind {
inline constexpr int keyword = 14, unit = 11, class_ = 7, module = 9, type_parameter = 25, struct_ = 22;
}
namespace sync_kind {
inline constexpr int full = 1, incremental = 2;
}

}  // namespace safegi::lsp
