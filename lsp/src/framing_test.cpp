// The base protocol's framing: partial reads, several messages per read, and
// every malformed header a client (or a fuzzer) can send.
#include "safegi/lsp/framing.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace safegi::lsp {
namespace {

// Bodies ("" never occurs as a body here) and "!error" entries, in order.
std::vector<std::string> drain(MessageReader& r) {
  std::vector<std::string> out;
  while (std::optional<Frame> f = r.next()) out.push_back(f->error.empty() ? f->body : "!" + f->error);
  return out;
}

TEST(Framing, OneMessageFedByteByByte) {
  const std::string wire = frame(R"({"a":1})");
  EXPECT_EQ(wire, "Content-Length: 7\r\n\r\n{\"a\":1}");
  MessageReader r;
  std::vector<std::string> got;
  for (char c : wire) {
    r.feed(std::string_view(&c, 1));
    for (const std::string& m : drain(r)) got.push_back(m);
  }
  EXPECT_EQ(got, std::vector<std::string>{R"({"a":1})"});
  EXPECT_EQ(r.pending_bytes(), 0u);
}

TEST(Framing, SeveralMessagesInOneReadAndOtherHeaders) {
  MessageReader r;
  r.feed(frame("{}") + "Content-Type: application/vscode-jsonrpc; charset=utf-8\r\ncontent-length:  2 \r\n\r\n[]" + frame("null"));
  EXPECT_EQ(drain(r), (std::vector<std::string>{"{}", "[]", "null"}));
}

TEST(Framing, AnEmptyBodyAndAStrayLineBreak) {
  MessageReader r;
  r.feed("Content-Length: 0\r\n\r\n\r\nContent-Length: 2\r\n\r\n{}");
  EXPECT_EQ(drain(r), (std::vector<std::string>{"", "{}"}));
}

TEST(Framing, BadLengthsAreErrorsAndTheNextMessageStillArrives) {
  const std::pair<std::string, std::string> cases[] = {
      {"Content-Length: -5\r\n\r\n", "!Content-Length is not a non-negative integer: '-5'"},
      {"Content-Length: 12abc\r\n\r\n", "!Content-Length is not a non-negative integer: '12abc'"},
      {"Content-Length:\r\n\r\n", "!Content-Length is not a non-negative integer: ''"},
      {"Content-Length: 99999999999999999999999\r\n\r\n",
       "!Content-Length 99999999999999999999999 exceeds the limit of 67108864 bytes"},
      {"Content-Length: 67108865\r\n\r\n", "!Content-Length 67108865 exceeds the limit of 67108864 bytes"},
      {"Content-Type: text/plain\r\n\r\n{\"x\":1}", "!missing Content-Length header"},
      {"Content-Lenght: 7\r\n\r\n{\"x\":1}", "!missing Content-Length header"},
      {"Content-Length: 2\r\nContent-Length: 3\r\n\r\n", "!two different Content-Length headers"},
      {"garbage\r\n\r\n", "!malformed header line (no ':')"},
  };
  for (const auto& [bad, error] : cases) {
    MessageReader r;
    r.feed(bad + frame(R"({"ok":true})"));
    const std::vector<std::string> got = drain(r);
    ASSERT_GE(got.size(), 2u) << bad;
    EXPECT_EQ(got.front(), error) << bad;
    EXPECT_EQ(got.back(), R"({"ok":true})") << bad;
  }
}

TEST(Framing, AHeaderThatNeverEndsIsDroppedWithoutGrowingWithoutBound) {
  MessageReader r;
  r.feed(std::string(20000, 'x'));
  EXPECT_EQ(drain(r), std::vector<std::string>{"!header block longer than 8192 bytes without an end"});
  EXPECT_LT(r.pending_bytes(), 100u);
  r.feed(std::string(50000, 'y'));
  EXPECT_TRUE(drain(r).empty());
  EXPECT_LT(r.pending_bytes(), 100u);
  r.feed(frame("{}"));
  EXPECT_EQ(drain(r), std::vector<std::string>{"{}"});
}

TEST(Framing, ResynchronisesOnAHeaderSplitAcrossReads) {
  MessageReader r;
  r.feed("Content-Length: x\r\n\r\njunk junk Content-Le");
  EXPECT_EQ(drain(r), std::vector<std::string>{"!Content-Length is not a non-negative integer: 'x'"});
  r.feed("ngth: 2\r\n\r\n{}");
  EXPECT_EQ(drain(r), std::vector<std::string>{"{}"});
}

TEST(Framing, AMessageCutShortStaysPending) {
  MessageReader r;
  r.feed("Content-Length: 10\r\n\r\n{\"a\"");
  EXPECT_TRUE(drain(r).empty());
  EXPECT_EQ(r.pending_bytes(), 4u);
}

TEST(Framing, ALongSessionDoesNotKeepWhatWasRead) {
  MessageReader r;
  for (int i = 0; i < 10000; ++i) {
    r.feed(frame(R"({"jsonrpc":"2.0","method":"x"})"));
    ASSERT_EQ(drain(r).size(), 1u);
  }
  EXPECT_EQ(r.pending_bytes(), 0u);
}

}  // namespace
}  // namespace safegi::lsp
