#include <safegi/diagnostics/source_manager.hpp>

#include <safegi/diagnostics/file.hpp>

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace safegi {
namespace {

// Offsets where each line starts; "\n", "\r\n" and a lone "\r" all end a line.
std::vector<std::uint32_t> compute_line_starts(std::string_view text) {
  std::vector<std::uint32_t> starts{0};
  if (text.empty()) return starts;
  if (std::memchr(text.data(), '\r', text.size()) == nullptr) {
    // Only "\n" ends lines (the usual case): memchr finds them a vector at a time.
    starts.reserve(text.size() / 24 + 1);
    const char* begin = text.data();
    const char* end = begin + text.size();
    for (const char* p = begin; p < end;) {
      const auto* nl = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
      if (nl == nullptr) break;
      starts.push_back(static_cast<std::uint32_t>(nl - begin + 1));
      p = nl + 1;
    }
    return starts;
  }
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') {
      starts.push_back(static_cast<std::uint32_t>(i + 1));
    } else if (text[i] == '\r') {
      if (i + 1 < text.size() && text[i + 1] == '\n') ++i;
      starts.push_back(static_cast<std::uint32_t>(i + 1));
    }
  }
  return starts;
}

}  // namespace

SourceManager::SourceManager() = default;
SourceManager::~SourceManager() = default;

FileId SourceManager::add_file(std::string path, std::string contents) {
  if (contents.size() > UINT32_MAX - 1) {
    // Offsets are 32-bit; the preprocessor rejects such inputs before this.
    contents.resize(UINT32_MAX - 1);
  }
  File file;
  file.path = std::move(path);
  auto shared = std::make_shared<const std::string>(std::move(contents));
  file.line_starts = std::make_shared<const std::vector<std::uint32_t>>(compute_line_starts(*shared));
  file.contents = std::move(shared);
  files_.push_back(std::move(file));
  return static_cast<FileId>(files_.size());
}

std::optional<FileId> SourceManager::load_file(const std::string& path, std::string* error) {
  std::optional<std::string> text = read_file(path, error);
  if (!text) return std::nullopt;
  return add_file(path, std::move(*text));
}

FileId SourceManager::add_inclusion(FileId id, SourceRange included_at) {
  File copy = file(id);
  copy.included_from = included_at;
  copy.line_directives.clear();
  files_.push_back(std::move(copy));
  return static_cast<FileId>(files_.size());
}

std::size_t SourceManager::file_count() const { return files_.size(); }

bool SourceManager::valid(FileId id) const { return id != kNoFile && id <= files_.size(); }

const SourceManager::File& SourceManager::file(FileId id) const {
  if (!valid(id)) throw std::out_of_range("SourceManager: invalid FileId");
  return files_[id - 1];
}

std::string_view SourceManager::text(FileId id) const { return *file(id).contents; }

const std::string& SourceManager::path(FileId id) const { return file(id).path; }

std::uint32_t SourceManager::line_count(FileId id) const {
  return static_cast<std::uint32_t>(file(id).line_starts->size());
}

std::string_view SourceManager::line_text(FileId id, std::uint32_t line) const {
  const File& f = file(id);
  const auto& starts = *f.line_starts;
  if (line == 0 || line > starts.size()) return {};
  std::string_view text = *f.contents;
  std::size_t begin = starts[line - 1];
  std::size_t end = line < starts.size() ? starts[line] : text.size();
  while (end > begin && (text[end - 1] == '\n' || text[end - 1] == '\r')) --end;
  return text.substr(begin, end - begin);
}

SourceLocation SourceManager::location_of(FileId id, std::uint32_t offset) const {
  const File& f = file(id);
  offset = std::min<std::uint32_t>(offset, static_cast<std::uint32_t>(f.contents->size()));
  const auto& starts = *f.line_starts;
  auto it = std::upper_bound(starts.begin(), starts.end(), offset);
  auto line = static_cast<std::uint32_t>(it - starts.begin());  // >= 1 since starts[0] == 0
  return SourceLocation{id, offset, line, offset - starts[line - 1] + 1};
}

SourceLocation SourceManager::location_after(FileId id, std::uint32_t offset, std::uint32_t& line_hint) const {
  const File& f = file(id);
  const auto& starts = *f.line_starts;
  offset = std::min<std::uint32_t>(offset, static_cast<std::uint32_t>(f.contents->size()));
  if (line_hint == 0 || line_hint > starts.size() || starts[line_hint - 1] > offset) {
    SourceLocation location = location_of(id, offset);
    line_hint = location.line;
    return location;
  }
  // A token is mostly on the hint's line or the next few; past those (a skipped #if group), search.
  for (int step = 0; line_hint < starts.size() && starts[line_hint] <= offset; ++step) {
    if (step == 4) {
      line_hint = static_cast<std::uint32_t>(std::upper_bound(starts.begin() + line_hint, starts.end(), offset) -
                                             starts.begin());
      break;
    }
    ++line_hint;
  }
  return SourceLocation{id, offset, line_hint, offset - starts[line_hint - 1] + 1};
}

SourceRange SourceManager::range_of(FileId id, std::uint32_t begin_offset, std::uint32_t end_offset) const {
  return SourceRange{location_of(id, begin_offset), location_of(id, end_offset)};
}

void SourceManager::set_included_from(FileId id, SourceRange directive) {
  file(id);  // validates
  files_[id - 1].included_from = directive;
}

SourceRange SourceManager::included_from(FileId id) const { return file(id).included_from; }

std::vector<SourceRange> SourceManager::include_chain(FileId id) const {
  std::vector<SourceRange> chain;
  // Bounded by the number of files, so a corrupted table cannot loop forever.
  for (SourceRange at = included_from(id); at.valid() && chain.size() <= files_.size();
       at = included_from(at.begin.file)) {
    chain.push_back(at);
  }
  std::reverse(chain.begin(), chain.end());
  return chain;
}

ExpansionId SourceManager::add_expansion(MacroExpansion expansion) {
  expansions_.push_back(expansion);
  return static_cast<ExpansionId>(expansions_.size());
}

const MacroExpansion& SourceManager::expansion(ExpansionId id) const {
  if (id == kNoExpansion || id > expansions_.size()) {
    throw std::out_of_range("SourceManager: invalid ExpansionId");
  }
  return expansions_[id - 1];
}

std::size_t SourceManager::expansion_count() const { return expansions_.size(); }

void SourceManager::add_line_directive(FileId id, std::uint32_t offset, std::uint32_t line,
                                       std::optional<std::string> file_name,
                                       std::optional<std::uint32_t> source_string) {
  file(id);
  LineDirective directive;
  directive.offset = offset;
  directive.physical_line = location_of(id, offset).line;
  directive.line = line;
  if (file_name) directive.file_name = save_string(*file_name);
  directive.source_string = source_string;
  auto& list = files_[id - 1].line_directives;
  // Inherit the name and source string of the previous directive when not given.
  if (!list.empty()) {
    if (!file_name) directive.file_name = list.back().file_name;
    if (!source_string) directive.source_string = list.back().source_string;
  }
  list.push_back(directive);
}

PresumedLocation SourceManager::presumed(SourceLocation location) const {
  PresumedLocation result;
  if (!valid(location.file)) return result;
  const File& f = file(location.file);
  result.file_name = f.path;
  result.line = location.line;
  result.column = location.column;
  const auto& list = f.line_directives;
  auto it = std::upper_bound(list.begin(), list.end(), location.offset,
                             [](std::uint32_t offset, const LineDirective& d) { return offset < d.offset; });
  if (it != list.begin()) {
    const LineDirective& d = *(it - 1);
    result.line = d.line + (location.line - d.physical_line);
    if (!d.file_name.empty()) result.file_name = d.file_name;
    result.source_string = d.source_string;
  }
  return result;
}

std::string_view SourceManager::save_string(std::string_view text) {
  return strings_.emplace_back(text);
}

}  // namespace safegi
