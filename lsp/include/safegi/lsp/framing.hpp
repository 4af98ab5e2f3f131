#pragma once
// The base protocol of LSP: each JSON-RPC message is a body preceded by
// headers, `Content-Length: N\r\n\r\n` at least. MessageReader takes bytes as
// they arrive — split anywhere, several messages in one read — and hands out
// whole bodies. A frame it cannot read (no or a malformed Content-Length, a
// length over the limit, a header block that never ends) comes out as an
// error, after which the reader resynchronises on the next `Content-Length`
// header: one bad frame costs one message, never the connection.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace safegi::lsp {

struct FramingLimits {
  std::size_t max_header_bytes = 8u << 10;  // one header block, terminator included
  std::size_t max_body_bytes = 64u << 20;   // a larger Content-Length is refused
};

struct Frame {
  std::string body;   // the message, when `error` is empty
  std::string error;  // why a frame was dropped ("missing Content-Length header")
};

class MessageReader {
 public:
  explicit MessageReader(FramingLimits limits = {}) : limits_(limits) {}

  void feed(std::string_view bytes);
  // The next message or framing error; nothing until more bytes arrive.
  std::optional<Frame> next();
  // Received bytes that are not part of a message handed out yet: what a
  // connection closed in the middle of a message leaves.
  std::size_t pending_bytes() const { return buffer_.size() - start_; }

 private:
  std::optional<Frame> read_header();
  void compact();

  FramingLimits limits_;
  std::string buffer_;
  std::size_t start_ = 0;                   // bytes before it are consumed
  std::optional<std::size_t> body_length_;  // a header was read; its body is awaited
  bool resynchronising_ = false;            // after an error: skip to the next Content-Length
};

// `Content-Length: N\r\n\r\n` + body.
std::string frame(std::string_view body);

}  // namespace safegi::lsp
