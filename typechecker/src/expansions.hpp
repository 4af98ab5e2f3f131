#pragma once
// Which macro expansion produced the code a diagnostic points at, so the
// rendered diagnostic carries its "in expansion of macro X" notes.
//
// The AST keeps source ranges only, so the expansion is found from the
// preprocessed tokens: the tokens that begin where the diagnostic's range
// begins. A macro expanded several times yields tokens with the same spelling
// location; then the expansion whose outermost site lies inside `context`
// (the innermost statement the user wrote) is taken, and none when that is
// still ambiguous (the error itself still points at the macro's definition).

#include <cstdint>
#include <unordered_map>
#include <vector>

#include <safegi/diagnostics/source_manager.hpp>
#include <safegi/lexer/token.hpp>

namespace safegi::detail {

class ExpansionFinder {
 public:
  ExpansionFinder() = default;
  ExpansionFinder(const std::vector<Token>& tokens, const SourceManager& sources);

  ExpansionId find(SourceRange range, SourceRange context) const;
  // Some macro expansion produced a token spelled where `range` begins.
  bool from_macro(SourceRange range) const { return range.valid() && at_.count(key(range.begin)) != 0; }

 private:
  static std::uint64_t key(SourceLocation at) { return (std::uint64_t{at.file} << 32) | at.offset; }
  bool site_within(ExpansionId id, SourceRange context) const;

  const SourceManager* sources_ = nullptr;
  std::unordered_map<std::uint64_t, std::vector<ExpansionId>> at_;  // spelling begin -> expansions, in token order
};

}  // namespace safegi::detail
