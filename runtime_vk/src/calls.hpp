#pragma once
// The thin dispatch layer every Vulkan call of runtime_vk goes through:
// SAFEGI_VK(vkCmdDispatch, cmd, x, y, z) calls the loader's entry point and,
// while a trace sink is set (set_call_trace), reports the call's name and
// scalar arguments. Results are checked with check().
#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>

namespace safegi::vk::detail {

bool tracing();
void trace(std::string line);
// "bytes <count> fnv1a64:<hex>": what a call hands over, for the trace.
void trace_bytes(std::string_view what, std::span<const std::byte> bytes);

// What the trace shows of the create infos and descriptor writes (sizes,
// formats, sets, bindings, ranges); other pointers are "h" (their address varies).
std::string describe(const VkBufferCreateInfo* info);
std::string describe(const VkImageCreateInfo* info);
std::string describe(const VkDescriptorSetLayoutCreateInfo* info);
std::string describe(const VkPipelineLayoutCreateInfo* info);
std::string describe(const VkWriteDescriptorSet* write);
std::string describe(const VkComputePipelineCreateInfo* info);

template <class A>
void append_argument(std::string& line, const A& argument) {
  line += ' ';
  if constexpr (requires { describe(argument); })
    line += argument ? describe(argument) : "0";
  else if constexpr (std::is_null_pointer_v<A>)
    line += '0';
  else if constexpr (std::is_pointer_v<A>)
    line += argument ? "h" : "0";
  else if constexpr (std::is_enum_v<A>)
    line += std::to_string(static_cast<long long>(argument));
  else if constexpr (std::is_floating_point_v<A>)
    line += std::to_string(argument);
  else if constexpr (std::is_integral_v<A>)
    line += std::to_string(argument);
  else
    line += '?';
}

template <class Function, class... Arguments>
auto call(const char* name, Function* function, Arguments... arguments) {
  if (tracing()) {
    std::string line = name;
    (append_argument(line, arguments), ...);
    trace(std::move(line));
  }
  return function(arguments...);
}

// A Vulkan struct with its sType set and every other member zero (a
// designated sType alone leaves the rest to -Wmissing-field-initializers).
template <class Info>
Info make(VkStructureType type) {
  Info info{};
  info.sType = type;
  return info;
}

// Throws VulkanError "safegi::vk: <what> failed: VK_ERROR_..." unless VK_SUCCESS.
void check(VkResult result, std::string_view what);
std::string result_name(VkResult result);

}  // namespace safegi::vk::detail

#define SAFEGI_VK(function, ...) ::safegi::vk::detail::call(#function, function, __VA_ARGS__)
