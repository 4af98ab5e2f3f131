#include "safegi/symbol_table/spirv_interface.hpp"

#include <unordered_map>

#include "safegi/symbol_table/error.hpp"

namespace safegi::gl {
namespace {

// From the SPIR-V specification (unified 1.6), section 3.
constexpr std::uint32_t kMagic = 0x07230203;
constexpr std::uint32_t kOpName = 5, kOpVariable = 59, kOpDecorate = 71;
constexpr std::uint32_t kDecorationLocation = 30;
constexpr std::uint32_t kUniformConstant = 0, kInput = 1, kOutput = 3;
constexpr std::size_t kHeaderWords = 5;

}  // namespace

std::string spirv_literal_string(std::span<const std::uint32_t> words) {
  std::string text;
  for (std::uint32_t word : words) {
    for (int shift = 0; shift < 32; shift += 8) {
      const char c = static_cast<char>((word >> shift) & 0xff);
      if (c == '\0') return text;
      text += c;
    }
  }
  return text;
}

void for_each_spirv_instruction(std::span<const std::uint32_t> words, const std::string& name,
                                const std::function<void(std::uint32_t, std::span<const std::uint32_t>)>& visit) {
  if (words.size() < kHeaderWords || words[0] != kMagic)
    throw ShaderError(name + ": error: not a SPIR-V module (no magic number 0x07230203 in its first word)");
  for (std::size_t at = kHeaderWords; at < words.size();) {
    const std::uint32_t count = words[at] >> 16, opcode = words[at] & 0xffff;
    if (count == 0 || at + count > words.size())
      throw ShaderError(name + ": error: truncated SPIR-V instruction at word " + std::to_string(at));
    visit(opcode, words.subspan(at + 1, count - 1));
    at += count;
  }
}

SpirvInterface read_spirv_interface(std::span<const std::uint32_t> words, const std::string& name) {
  std::unordered_map<std::uint32_t, std::string> names;
  std::unordered_map<std::uint32_t, std::uint32_t> storage, locations;
  for_each_spirv_instruction(words, name, [&](std::uint32_t opcode, std::span<const std::uint32_t> operands) {
    if (opcode == kOpName && operands.size() >= 2) names[operands[0]] = spirv_literal_string(operands.subspan(1));
    if (opcode == kOpVariable && operands.size() >= 3) storage[operands[1]] = operands[2];
    if (opcode == kOpDecorate && operands.size() >= 3 && operands[1] == kDecorationLocation)
      locations[operands[0]] = operands[2];
  });
  SpirvInterface interface;
  for (const auto& [id, location] : locations) {
    const auto named = names.find(id);
    const auto kind = storage.find(id);
    if (named == names.end() || kind == storage.end() || named->second.empty()) continue;
    const int value = static_cast<int>(location);
    if (kind->second == kUniformConstant) interface.uniforms.emplace(named->second, value);
    else if (kind->second == kInput) interface.inputs.emplace(named->second, value);
    else if (kind->second == kOutput) interface.outputs.emplace(named->second, value);
  }
  return interface;
}

}  // namespace safegi::gl
