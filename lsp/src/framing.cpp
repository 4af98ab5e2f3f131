#include "safegi/lsp/framing.hpp"

#include <algorithm>
#include <cctype>

namespace safegi::lsp {
namespace {

constexpr std::string_view kTerminator = "\r\n\r\n";
constexpr std::string_view kLengthHeader = "content-length";

bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// Where `Content-Length` starts in `text` (any case), or npos.
std::size_t find_length_header(std::string_view text) {
  for (std::size_t i = 0; i + kLengthHeader.size() <= text.size(); ++i)
    if (iequals(text.substr(i, kLengthHeader.size()), kLengthHeader)) return i;
  return std::string_view::npos;
}

Frame error(std::string message) { return Frame{{}, std::move(message)}; }

}  // namespace

void MessageReader::feed(std::string_view bytes) { buffer_.append(bytes); }

void MessageReader::compact() {
  // Drop consumed bytes once they dominate, so a long session stays small.
  if (start_ > 4096 && start_ * 2 > buffer_.size()) {
    buffer_.erase(0, start_);
    start_ = 0;
  }
}

std::optional<Frame> MessageReader::read_header() {
  const std::string_view pending = std::string_view(buffer_).substr(start_);
  const std::size_t end = pending.find(kTerminator);
  if (end == std::string_view::npos) {
    if (pending.size() < limits_.max_header_bytes) return std::nullopt;  // wait for the rest
    start_ = buffer_.size();
    resynchronising_ = true;
    return error("header block longer than " + std::to_string(limits_.max_header_bytes) + " bytes without an end");
  }
  const std::string_view block = pending.substr(0, end);
  const std::size_t block_start = start_;
  start_ += end + kTerminator.size();
  // A bad block: look for the next Content-Length after it, or, when a line
  // of it is junk, after its first byte (a good header may follow the junk).
  auto fail = [&](std::string message, bool rescan_block = false) {
    if (rescan_block) start_ = block_start + 1;
    resynchronising_ = true;
    return error(std::move(message));
  };
  if (end + kTerminator.size() > limits_.max_header_bytes)
    return fail("header block longer than " + std::to_string(limits_.max_header_bytes) + " bytes");
  std::optional<std::size_t> length;
  for (std::size_t line_start = 0; line_start <= block.size();) {
    std::size_t line_end = block.find("\r\n", line_start);
    if (line_end == std::string_view::npos) line_end = block.size();
    const std::string_view line = block.substr(line_start, line_end - line_start);
    line_start = line_end + 2;
    if (line.empty()) continue;  // a stray line break before the headers
    const std::size_t colon = line.find(':');
    if (colon == std::string_view::npos) return fail("malformed header line (no ':')", true);
    if (!iequals(trim(line.substr(0, colon)), kLengthHeader)) continue;  // Content-Type and others: UTF-8 JSON is all we read
    const std::string_view value = trim(line.substr(colon + 1));
    const bool digits = !value.empty() && std::all_of(value.begin(), value.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!digits) return fail("Content-Length is not a non-negative integer: '" + std::string(value.substr(0, 32)) + "'");
    std::size_t n = 0;
    bool too_large = value.size() > 18;
    for (char c : value) n = too_large ? n : n * 10 + static_cast<std::size_t>(c - '0');
    too_large = too_large || n > limits_.max_body_bytes;
    if (too_large)
      return fail("Content-Length " + std::string(value.substr(0, 32)) + " exceeds the limit of " +
                  std::to_string(limits_.max_body_bytes) + " bytes");
    if (length && *length != n) return fail("two different Content-Length headers");
    length = n;
  }
  if (!length) return fail("missing Content-Length header");
  body_length_ = length;
  return std::nullopt;
}

std::optional<Frame> MessageReader::next() {
  for (;;) {
    compact();
    if (resynchronising_) {
      const std::string_view pending = std::string_view(buffer_).substr(start_);
      const std::size_t at = find_length_header(pending);
      if (at == std::string_view::npos) {
        // Keep a tail that may be the start of a header split across reads.
        if (pending.size() > kLengthHeader.size()) start_ = buffer_.size() - kLengthHeader.size();
        return std::nullopt;
      }
      start_ += at;
      resynchronising_ = false;
    }
    if (!body_length_) {
      std::optional<Frame> failed = read_header();
      if (failed) return failed;
      if (!body_length_) return std::nullopt;
    }
    if (buffer_.size() - start_ < *body_length_) return std::nullopt;
    Frame message{buffer_.substr(start_, *body_length_), {}};
    start_ += *body_length_;
    body_length_.reset();
    return message;
  }
}

std::string frame(std::string_view body) {
  std::string out = "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n";
  out.append(body);
  return out;
}

}  // namespace safegi::lsp
