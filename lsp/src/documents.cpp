#include "documents.hpp"

#include <algorithm>

namespace safegi::lsp {

void apply_change(Document& document, const json& change, Encoding encoding) {
  std::string text = string_member(change, "text");
  auto range = change.find("range");
  if (range == change.end()) {
    document.text = std::move(text);
    return;
  }
  const LineIndex lines(document.text);
  std::size_t begin = lines.offset_of(position_from_json(member(*range, "start")), encoding);
  std::size_t end = lines.offset_of(position_from_json(member(*range, "end")), encoding);
  if (end < begin) std::swap(begin, end);  // a reversed range still names the same text
  document.text.replace(begin, end - begin, text);
}

}  // namespace safegi::lsp
