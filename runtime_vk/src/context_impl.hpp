#pragma once
// The Vulkan objects behind a Context, shared by the resource and pipeline
// sources (not installed).
#include <vulkan/vulkan.h>

#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "safegi/runtime_vk/context.hpp"

namespace safegi::vk::detail {

struct ContextImpl {
  ContextInfo info;
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkPhysicalDeviceMemoryProperties memory{};
  VkPhysicalDeviceLimits limits{};
  VkDevice device = VK_NULL_HANDLE;
  std::uint32_t queue_family = 0;
  VkQueue queue = VK_NULL_HANDLE;
  VkCommandPool pool = VK_NULL_HANDLE;

  std::mutex messages_mutex;
  std::vector<std::string> messages;

  ~ContextImpl();
  // A memory type allowed by `type_bits` with all of `flags`; throws ResourceError.
  std::uint32_t memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags flags) const;
  // Records one command buffer, submits it and waits for it.
  void submit(const std::function<void(VkCommandBuffer)>& record);
};

}  // namespace safegi::vk::detail
