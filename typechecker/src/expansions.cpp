#include "expansions.hpp"

#include <algorithm>

namespace safegi::detail {

ExpansionFinder::ExpansionFinder(const std::vector<Token>& tokens, const SourceManager& sources) : sources_(&sources) {
  for (const Token& t : tokens) {
    if (t.expansion == kNoExpansion || !t.range.valid()) continue;
    std::vector<ExpansionId>& ids = at_[key(t.range.begin)];
    if (std::find(ids.begin(), ids.end(), t.expansion) == ids.end()) ids.push_back(t.expansion);
  }
}

bool ExpansionFinder::site_within(ExpansionId id, SourceRange context) const {
  // The outermost expansion's site is in the file the user wrote.
  for (std::size_t depth = 0; depth <= sources_->expansion_count(); ++depth) {
    const MacroExpansion& e = sources_->expansion(id);
    if (e.parent == kNoExpansion) {
      const SourceLocation at = e.expansion_site.begin;
      return at.file == context.begin.file && at.offset >= context.begin.offset && at.offset < context.end.offset;
    }
    id = e.parent;
  }
  return false;
}

ExpansionId ExpansionFinder::find(SourceRange range, SourceRange context) const {
  if (!sources_ || !range.valid()) return kNoExpansion;
  auto it = at_.find(key(range.begin));
  if (it == at_.end()) return kNoExpansion;
  const std::vector<ExpansionId>& ids = it->second;
  if (ids.size() == 1) return ids.front();
  ExpansionId found = kNoExpansion;
  for (ExpansionId id : ids) {
    if (!context.valid() || !site_within(id, context)) continue;
    if (found != kNoExpansion) return kNoExpansion;  // still ambiguous
    found = id;
  }
  return found;
}

}  // namespace safegi::detail
