#pragma once
// What a SPIR-V module says about its interface: the location of each named
// default-block uniform, input and output. A GL_ARB_gl_spirv program need not
// keep names (Mesa keeps none, so glGetUniformLocation answers -1); runtime_gl
// looks the locations up here instead, by the names the symbol table uses.
// No GL: reads the module's OpName, OpVariable and OpDecorate Location.
#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <string>

namespace safegi::gl {

struct SpirvInterface {
  std::map<std::string, int, std::less<>> uniforms;  // UniformConstant: default-block uniforms and samplers
  std::map<std::string, int, std::less<>> inputs;    // Input (vertex attributes, for a vertex module)
  std::map<std::string, int, std::less<>> outputs;   // Output (fragment outputs, for a fragment module)
};

// Throws ShaderError when `words` is not a SPIR-V module (bad magic, truncated
// instruction); `name` labels the message.
SpirvInterface read_spirv_interface(std::span<const std::uint32_t> words, const std::string& name);

// The walk read_spirv_interface makes, for readers of other instructions (tests
// that compare a symbol table with a module's decorations): each instruction's
// opcode and operands (its words after the first), in order. Throws as above.
void for_each_spirv_instruction(std::span<const std::uint32_t> words, const std::string& name,
                                const std::function<void(std::uint32_t opcode, std::span<const std::uint32_t> operands)>& visit);
// A literal string operand: UTF-8 bytes packed little-endian into words, NUL-terminated.
std::string spirv_literal_string(std::span<const std::uint32_t> words);

}  // namespace safegi::gl
