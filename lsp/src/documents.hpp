#pragma once
// The documents the client has open: their text as the client sees it (full
// or incremental sync), and the analysis of that text.

#include <cstdint>
#include <memory>
#include <string>

#include "analysis.hpp"
#include "protocol.hpp"

namespace safegi::lsp {

struct Document {
  std::string uri;
  std::string path;         // the file the URI names; the URI itself for another scheme (untitled:)
  std::string language_id;
  std::int64_t version = 0;
  std::string text;
  std::shared_ptr<const Analysis> analysis;  // of `text`; diagnostics, hover and definition read it
  // The last analysis that got as far as the checker: its vocabulary names
  // completions while the text being typed does not parse.
  std::shared_ptr<const Analysis> last_checked;
};

// One TextDocumentContentChangeEvent: with a range, an incremental edit (its
// positions in `encoding`, clamped to the text); without, the whole text.
// A malformed change is a RequestError and leaves the text as it was.
void apply_change(Document& document, const json& change, Encoding encoding);

}  // namespace safegi::lsp
