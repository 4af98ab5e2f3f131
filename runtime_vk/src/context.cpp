#include "safegi/runtime_vk/context.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "calls.hpp"
#include "context_impl.hpp"

namespace safegi::vk {
namespace detail {
namespace {

std::function<void(std::string_view)>& trace_sink() {
  static std::function<void(std::string_view)> sink;
  return sink;
}

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

VKAPI_ATTR VkBool32 VKAPI_CALL on_validation_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                     VkDebugUtilsMessageTypeFlagsEXT,
                                                     const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  auto* impl = static_cast<ContextImpl*>(user);
  const std::string message =
      std::string(severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning") + ": " +
      (data && data->pMessage ? data->pMessage : "(no message)");
  if (impl->info.validation == Validation::fatal) {
    std::fprintf(stderr, "safegi::vk: validation layer %s\n", message.c_str());
    std::fflush(stderr);
    std::abort();
  }
  const std::lock_guard lock(impl->messages_mutex);
  impl->messages.push_back(message);
  return VK_FALSE;
}

bool layer_available(const char* name) {
  std::uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  return std::any_of(layers.begin(), layers.end(),
                     [name](const auto& l) { return std::strcmp(l.layerName, name) == 0; });
}

void create_instance(ContextImpl& impl) {
  const bool validation = impl.info.validation != Validation::off;
  if (validation && !layer_available(kValidationLayer))
    throw ContextError(
        "safegi::vk: the validation layer VK_LAYER_KHRONOS_validation is not installed "
        "(Debian: vulkan-validationlayers), or set SAFEGI_VK_VALIDATION=0");
  auto app = make<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
  app.pApplicationName = "safegi";
  app.pEngineName = "safegi runtime_vk";
  app.apiVersion = VK_API_VERSION_1_2;
  auto messenger = make<VkDebugUtilsMessengerCreateInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
  messenger.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                          VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger.pfnUserCallback = on_validation_message;
  messenger.pUserData = &impl;
  const char* layers[] = {kValidationLayer};
  const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
  auto create = make<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
  create.pApplicationInfo = &app;
  if (validation) {
    create.enabledLayerCount = 1;
    create.ppEnabledLayerNames = layers;
    create.enabledExtensionCount = 1;
    create.ppEnabledExtensionNames = extensions;
    create.pNext = &messenger;  // also reports on instance creation and destruction
  }
  const VkResult result = SAFEGI_VK(vkCreateInstance, &create, nullptr, &impl.instance);
  if (result != VK_SUCCESS)
    throw ContextError("safegi::vk: no Vulkan instance (vkCreateInstance: " + result_name(result) +
                       "); is a Vulkan driver installed? (Debian: mesa-vulkan-drivers for lavapipe)");
  if (validation) {
    auto create_messenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(impl.instance, "vkCreateDebugUtilsMessengerEXT"));
    check(SAFEGI_VK(create_messenger, impl.instance, &messenger, nullptr, &impl.messenger),
          "vkCreateDebugUtilsMessengerEXT");
  }
}

std::string device_list(const std::vector<std::string>& names) {
  std::string list;
  for (std::size_t i = 0; i < names.size(); ++i) list += "\n  " + std::to_string(i) + ": " + names[i];
  return list.empty() ? " none" : list;
}

void choose_device(ContextImpl& impl, const std::string& choice) {
  std::uint32_t count = 0;
  SAFEGI_VK(vkEnumeratePhysicalDevices, impl.instance, &count, static_cast<VkPhysicalDevice*>(nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  check(SAFEGI_VK(vkEnumeratePhysicalDevices, impl.instance, &count, devices.data()), "vkEnumeratePhysicalDevices");
  if (devices.empty())
    throw ContextError(
        "safegi::vk: no Vulkan device (is a driver installed? Debian: mesa-vulkan-drivers for lavapipe)");
  std::vector<std::string> names;
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(d, &p);
    names.emplace_back(p.deviceName);
  }
  impl.info.devices = names;
  auto compute_family = [](VkPhysicalDevice d) -> std::optional<std::uint32_t> {
    std::uint32_t n = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(d, &n, nullptr);
    std::vector<VkQueueFamilyProperties> families(n);
    vkGetPhysicalDeviceQueueFamilyProperties(d, &n, families.data());
    for (std::uint32_t i = 0; i < n; ++i)
      if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) return i;
    return std::nullopt;
  };
  std::optional<std::uint32_t> chosen;
  const bool by_index =
      !choice.empty() && std::all_of(choice.begin(), choice.end(), [](unsigned char c) { return std::isdigit(c); });
  for (std::uint32_t i = 0; i < devices.size() && !chosen; ++i) {
    if (by_index         ? std::to_string(i) == choice
        : choice.empty() ? compute_family(devices[i]).has_value()
                         : lower(names[i]).find(lower(choice)) != std::string::npos)
      chosen = i;
  }
  if (!chosen)
    throw ContextError("safegi::vk: no Vulkan device " +
                       (choice.empty() ? std::string("with a compute queue") : "matching '" + choice + "'") +
                       " (SAFEGI_VK_DEVICE: an index or part of a name); the devices are:" + device_list(names));
  const auto family = compute_family(devices[*chosen]);
  if (!family) throw ContextError("safegi::vk: device " + names[*chosen] + " has no compute queue");
  impl.physical = devices[*chosen];
  impl.queue_family = *family;
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(impl.physical, &properties);
  vkGetPhysicalDeviceMemoryProperties(impl.physical, &impl.memory);
  impl.limits = properties.limits;
  impl.info.device_index = *chosen;
  impl.info.device_name = properties.deviceName;
  impl.info.api_version = properties.apiVersion;
  impl.info.software = properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  auto driver = make<VkPhysicalDeviceDriverProperties>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES);
  auto properties2 = make<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2);
  properties2.pNext = &driver;
  if (VK_API_VERSION_MINOR(properties.apiVersion) >= 2 || VK_API_VERSION_MAJOR(properties.apiVersion) > 1) {
    vkGetPhysicalDeviceProperties2(impl.physical, &properties2);
    impl.info.driver = std::string(driver.driverName) + ' ' + driver.driverInfo;
  }
}

void create_device(ContextImpl& impl) {
  const float priority = 1.0f;
  auto queue = make<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
  queue.queueFamilyIndex = impl.queue_family;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  auto create = make<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
  create.queueCreateInfoCount = 1;
  create.pQueueCreateInfos = &queue;
  check(SAFEGI_VK(vkCreateDevice, impl.physical, &create, nullptr, &impl.device), "vkCreateDevice");
  SAFEGI_VK(vkGetDeviceQueue, impl.device, impl.queue_family, 0u, &impl.queue);
  auto pool = make<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
  pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool.queueFamilyIndex = impl.queue_family;
  check(SAFEGI_VK(vkCreateCommandPool, impl.device, &pool, nullptr, &impl.pool), "vkCreateCommandPool");
}

}  // namespace

bool tracing() { return static_cast<bool>(trace_sink()); }
void trace(std::string line) {
  if (trace_sink()) trace_sink()(line);
}
void trace_bytes(std::string_view what, std::span<const std::byte> bytes) {
  if (!tracing()) return;
  std::uint64_t hash = 14695981039346656037ull;  // FNV-1a 64
  for (std::byte b : bytes) hash = (hash ^ static_cast<std::uint64_t>(b)) * 1099511628211ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  trace(std::string(what) + " bytes " + std::to_string(bytes.size()) + " fnv1a64:" + hex);
}

std::string describe(const VkBufferCreateInfo* info) {
  return "{size " + std::to_string(info->size) + " usage " + std::to_string(info->usage) + '}';
}
std::string describe(const VkImageCreateInfo* info) {
  return "{format " + std::to_string(info->format) + ' ' + std::to_string(info->extent.width) + 'x' +
         std::to_string(info->extent.height) + " usage " + std::to_string(info->usage) + '}';
}
std::string describe(const VkDescriptorSetLayoutCreateInfo* info) {
  std::string text = "{";
  for (std::uint32_t i = 0; i < info->bindingCount; ++i) {
    const VkDescriptorSetLayoutBinding& b = info->pBindings[i];
    text += (i ? " " : "") + std::string("binding ") + std::to_string(b.binding) + " type " +
            std::to_string(b.descriptorType) + " count " + std::to_string(b.descriptorCount);
  }
  return text + '}';
}
std::string describe(const VkPipelineLayoutCreateInfo* info) {
  std::string text = "{sets " + std::to_string(info->setLayoutCount);
  for (std::uint32_t i = 0; i < info->pushConstantRangeCount; ++i)
    text += " push " + std::to_string(info->pPushConstantRanges[i].offset) + '+' +
            std::to_string(info->pPushConstantRanges[i].size);
  return text + '}';
}
std::string describe(const VkWriteDescriptorSet* write) {
  return "{binding " + std::to_string(write->dstBinding) + " type " + std::to_string(write->descriptorType) +
         " count " + std::to_string(write->descriptorCount) + '}';
}
std::string describe(const VkComputePipelineCreateInfo* info) {
  const VkSpecializationInfo* s = info->stage.pSpecializationInfo;
  std::string text = "{entry " + std::string(info->stage.pName);
  for (std::uint32_t i = 0; s && i < s->mapEntryCount; ++i)
    text +=
        " constant " + std::to_string(s->pMapEntries[i].constantID) + '@' + std::to_string(s->pMapEntries[i].offset);
  return text + '}';
}

std::string result_name(VkResult result) {
  switch (result) {
    case VK_SUCCESS:
      return "VK_SUCCESS";
    case VK_NOT_READY:
      return "VK_NOT_READY";
    case VK_TIMEOUT:
      return "VK_TIMEOUT";
    case VK_INCOMPLETE:
      return "VK_INCOMPLETE";
    case VK_ERROR_OUT_OF_HOST_MEMORY:
      return "VK_ERROR_OUT_OF_HOST_MEMORY";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY:
      return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
    case VK_ERROR_INITIALIZATION_FAILED:
      return "VK_ERROR_INITIALIZATION_FAILED";
    case VK_ERROR_DEVICE_LOST:
      return "VK_ERROR_DEVICE_LOST";
    case VK_ERROR_LAYER_NOT_PRESENT:
      return "VK_ERROR_LAYER_NOT_PRESENT";
    case VK_ERROR_EXTENSION_NOT_PRESENT:
      return "VK_ERROR_EXTENSION_NOT_PRESENT";
    case VK_ERROR_FEATURE_NOT_PRESENT:
      return "VK_ERROR_FEATURE_NOT_PRESENT";
    case VK_ERROR_INCOMPATIBLE_DRIVER:
      return "VK_ERROR_INCOMPATIBLE_DRIVER";
    case VK_ERROR_INVALID_SHADER_NV:
      return "VK_ERROR_INVALID_SHADER_NV";
    default:
      return "VkResult " + std::to_string(static_cast<int>(result));
  }
}

void check(VkResult result, std::string_view what) {
  if (result != VK_SUCCESS) throw VulkanError("safegi::vk: " + std::string(what) + " failed: " + result_name(result));
}

ContextImpl::~ContextImpl() {
  if (device) {
    SAFEGI_VK(vkDeviceWaitIdle, device);
    if (pool) SAFEGI_VK(vkDestroyCommandPool, device, pool, static_cast<const VkAllocationCallbacks*>(nullptr));
    SAFEGI_VK(vkDestroyDevice, device, static_cast<const VkAllocationCallbacks*>(nullptr));
  }
  if (messenger) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    SAFEGI_VK(destroy, instance, messenger, static_cast<const VkAllocationCallbacks*>(nullptr));
  }
  if (instance) SAFEGI_VK(vkDestroyInstance, instance, static_cast<const VkAllocationCallbacks*>(nullptr));
}

std::uint32_t ContextImpl::memory_type(std::uint32_t type_bits, VkMemoryPropertyFlags flags) const {
  for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i)
    if ((type_bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & flags) == flags) return i;
  throw ResourceError("safegi::vk: device " + info.device_name + " has no memory type with flags " +
                      std::to_string(flags) + " for this resource");
}

void ContextImpl::submit(const std::function<void(VkCommandBuffer)>& record) {
  auto allocate = make<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
  allocate.commandPool = pool;
  allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocate.commandBufferCount = 1;
  VkCommandBuffer commands = VK_NULL_HANDLE;
  check(SAFEGI_VK(vkAllocateCommandBuffers, device, &allocate, &commands), "vkAllocateCommandBuffers");
  VkFence fence = VK_NULL_HANDLE;
  try {
    auto begin = make<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(SAFEGI_VK(vkBeginCommandBuffer, commands, &begin), "vkBeginCommandBuffer");
    record(commands);
    check(SAFEGI_VK(vkEndCommandBuffer, commands), "vkEndCommandBuffer");
    auto fence_info = make<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
    check(SAFEGI_VK(vkCreateFence, device, &fence_info, nullptr, &fence), "vkCreateFence");
    auto submit_info = make<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
    submit_info.commandBufferCount = 1;
    submit_info.pCommandBuffers = &commands;
    check(SAFEGI_VK(vkQueueSubmit, queue, 1u, &submit_info, fence), "vkQueueSubmit");
    check(SAFEGI_VK(vkWaitForFences, device, 1u, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
  } catch (...) {
    SAFEGI_VK(vkDeviceWaitIdle, device);
    if (fence) SAFEGI_VK(vkDestroyFence, device, fence, static_cast<const VkAllocationCallbacks*>(nullptr));
    SAFEGI_VK(vkFreeCommandBuffers, device, pool, 1u, &commands);
    throw;
  }
  SAFEGI_VK(vkDestroyFence, device, fence, static_cast<const VkAllocationCallbacks*>(nullptr));
  SAFEGI_VK(vkFreeCommandBuffers, device, pool, 1u, &commands);
}

}  // namespace detail

Validation validation_from_environment() {
  const char* value = std::getenv("SAFEGI_VK_VALIDATION");
  const std::string text = value ? detail::lower(value) : "";
  if (text.empty() || text == "0" || text == "off") return Validation::off;
  if (text == "1" || text == "on" || text == "record") return Validation::record;
  if (text == "fatal") return Validation::fatal;
  throw ContextError("safegi::vk: SAFEGI_VK_VALIDATION is '" + text + "'; expected 0, off, 1, on, record or fatal");
}

std::string describe(const ContextInfo& info) {
  std::string text = info.device_name + ", Vulkan " + std::to_string(VK_API_VERSION_MAJOR(info.api_version)) + '.' +
                     std::to_string(VK_API_VERSION_MINOR(info.api_version)) + '.' +
                     std::to_string(VK_API_VERSION_PATCH(info.api_version));
  if (!info.driver.empty()) text += ", " + info.driver;
  if (info.software) text += ", software";
  text += info.validation == Validation::off ? ", validation off" : ", validation on";
  return text;
}

Context::Context(ContextOptions options) : impl_(std::make_unique<detail::ContextImpl>()) {
  impl_->info.validation = options.validation.value_or(validation_from_environment());
  std::string choice;
  if (options.device) {
    choice = *options.device;
  } else if (const char* env = std::getenv("SAFEGI_VK_DEVICE")) {
    choice = env;
  }
  detail::create_instance(*impl_);
  detail::choose_device(*impl_, choice);
  detail::create_device(*impl_);
}

Context::~Context() = default;
Context::Context(Context&&) noexcept = default;
Context& Context::operator=(Context&&) noexcept = default;

const ContextInfo& Context::info() const { return impl_->info; }

std::vector<std::string> Context::take_validation_messages() {
  const std::lock_guard lock(impl_->messages_mutex);
  return std::exchange(impl_->messages, {});
}

void set_call_trace(std::function<void(std::string_view line)> sink) { detail::trace_sink() = std::move(sink); }

}  // namespace safegi::vk
