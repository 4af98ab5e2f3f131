#include "safegi/symbol_table/driver_log.hpp"

#include <cctype>
#include <regex>

namespace safegi::gl {
namespace {

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string trim(std::string_view text) {
  std::size_t begin = text.find_first_not_of(" \t\r");
  std::size_t end = text.find_last_not_of(" \t\r");
  return begin == std::string_view::npos ? std::string() : std::string(text.substr(begin, end - begin + 1));
}

std::string located(const StageSymbols& stage, const std::string& string_index, const std::string& line,
                    const std::string& column) {
  std::string where = stage.file_for_source_string(std::stoi(string_index)) + ':' + line;
  if (!column.empty() && column != "0") where += ':' + column;
  return where;
}

}  // namespace

std::string map_driver_log(std::string_view log, const StageSymbols& stage) {
  static const std::regex mesa(R"(^(\d+):(\d+)\((\d+)\): (error|warning): (.*)$)");
  static const std::regex nvidia(R"(^(\d+)\((\d+)\) : (error|warning) \w+: (.*)$)");
  static const std::regex generic(R"(^(ERROR|WARNING): (\d+):(\d+): (.*)$)");
  std::string mapped;
  std::size_t start = 0;
  while (start < log.size()) {
    std::size_t end = log.find('\n', start);
    if (end == std::string_view::npos) end = log.size();
    std::string line = trim(log.substr(start, end - start));
    start = end + 1;
    if (line.empty()) continue;
    std::smatch m;
    if (std::regex_match(line, m, mesa))
      mapped += located(stage, m[1], m[2], m[3]) + ": " + m[4].str() + ": " + m[5].str();
    else if (std::regex_match(line, m, nvidia))
      mapped += located(stage, m[1], m[2], "") + ": " + m[3].str() + ": " + m[4].str();
    else if (std::regex_match(line, m, generic))
      mapped += located(stage, m[2], m[3], "") + ": " + lower(m[1]) + ": " + trim(m[4].str());
    else
      mapped += stage.file + ": " + line;
    mapped += '\n';
  }
  return mapped;
}

}  // namespace safegi::gl
