// Choices as a message lists them: "a", "b" or "c".
#pragma once

#include <iterator>
#include <string>
#include <string_view>

namespace safegi::render {

// Each name quoted, commas between them and "or" before the last.
template <class Names>
std::string quoted_list(const Names& names) {
  std::string list;
  const size_t count = static_cast<size_t>(std::size(names));
  size_t i = 0;
  for (const auto& name : names) {
    if (i > 0) list.append(i + 1 == count ? " or " : ", ");
    list.append("\"").append(std::string_view(name)).append("\"");
    ++i;
  }
  return list;
}

}  // namespace safegi::render
