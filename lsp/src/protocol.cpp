#include "protocol.hpp"

namespace safegi::lsp {

json response(const json& id, json result) { return {{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}}; }

json error_response(const json& id, int code, const std::string& message) {
  return {{"jsonrpc", "2.0"}, {"id", id}, {"error", {{"code", code}, {"message", message}}}};
}

json notification(const std::string& method, json params) {
  return {{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}};
}

std::string serialize(const json& message) { return message.dump(-1, ' ', false, json::error_handler_t::replace); }

const json& member(const json& object, const char* name) {
  if (!object.is_object()) throw RequestError{error_code::invalid_params, "expected an object holding '" + std::string(name) + "'"};
  auto it = object.find(name);
  if (it == object.end()) throw RequestError{error_code::invalid_params, "missing '" + std::string(name) + "'"};
  return *it;
}

std::string string_member(const json& object, const char* name) {
  const json& value = member(object, name);
  if (!value.is_string()) throw RequestError{error_code::invalid_params, "'" + std::string(name) + "' must be a string"};
  return value.get<std::string>();
}

namespace {

std::uint32_t unsigned_member(const json& object, const char* name) {
  const json& value = member(object, name);
  // LSP's uinteger: 0 … 2^31 - 1.
  if (!value.is_number_integer() || value.get<std::int64_t>() < 0 || value.get<std::int64_t>() > 0x7fffffff)
    throw RequestError{error_code::invalid_params, "'" + std::string(name) + "' must be a non-negative integer"};
  return static_cast<std::uint32_t>(value.get<std::int64_t>());
}

}  // namespace

Position position_from_json(const json& value) { return {unsigned_member(value, "line"), unsigned_member(value, "character")}; }

json position_json(Position position) { return {{"line", position.line}, {"character", position.character}}; }

json range_json(Position begin, Position end) { return {{"start", position_json(begin)}, {"end", position_json(end)}}; }

}  // namespace safegi::lsp
