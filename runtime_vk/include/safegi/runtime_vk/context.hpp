#pragma once
// A headless Vulkan context: instance (with VK_LAYER_KHRONOS_validation when
// asked), one physical device, a logical device with one compute queue. No
// surface, no window. Every runtime_vk object is made from a Context and must
// be destroyed before it.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "safegi/symbol_table/error.hpp"

namespace safegi::vk {

// runtime_vk's errors are the symbol table's (safegi::gl::Error and kin): one
// hierarchy whose what() is the whole user-facing message.
using gl::BindingError;
using gl::ContextError;
using gl::Error;
using gl::ResourceError;
using gl::ShaderError;

// A Vulkan call that returned an error code: "safegi::vk: vkCreateBuffer failed: VK_ERROR_OUT_OF_DEVICE_MEMORY".
class VulkanError : public Error {
 public:
  using Error::Error;
};

enum class Validation {
  off,     // no layer
  record,  // VK_LAYER_KHRONOS_validation on; warnings and errors kept for take_validation_messages()
  fatal,   // on; the first warning or error is printed to stderr and aborts the process (tests)
};

// SAFEGI_VK_VALIDATION: 0/off (default), 1/on/record, fatal. Throws ContextError otherwise.
Validation validation_from_environment();

struct ContextOptions {
  std::optional<Validation> validation;  // unset: validation_from_environment()
  // Which physical device: its index in vkEnumeratePhysicalDevices order, or
  // a case-insensitive part of its name ("llvmpipe", "nvidia"). Unset:
  // SAFEGI_VK_DEVICE; empty: the first device with a compute queue.
  std::optional<std::string> device;
};

struct ContextInfo {
  std::string device_name;  // "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string driver;       // "llvmpipe Mesa 22.3.6 (LLVM 15.0.6)" where the driver says
  std::uint32_t device_index = 0;
  std::uint32_t api_version = 0;  // the device's VK_MAKE_API_VERSION
  bool software = false;          // VK_PHYSICAL_DEVICE_TYPE_CPU (lavapipe)
  Validation validation = Validation::off;
  std::vector<std::string> devices;  // every device's name, by index (for messages)
};

// "llvmpipe (LLVM 15.0.6, 256 bits), Vulkan 1.3.230, software, validation on"
std::string describe(const ContextInfo& info);

namespace detail {
struct ContextImpl;
}

class Context {
 public:
  // Throws ContextError: no Vulkan loader or device, the validation layer
  // asked for but not installed, no device matching the choice (the message
  // lists the devices).
  explicit Context(ContextOptions options = {});
  ~Context();
  Context(Context&&) noexcept;
  Context& operator=(Context&&) noexcept;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  const ContextInfo& info() const;
  // Validation messages (warnings and errors) since creation or the last call
  // (Validation::record).
  std::vector<std::string> take_validation_messages();

  detail::ContextImpl& impl() const { return *impl_; }

 private:
  std::unique_ptr<detail::ContextImpl> impl_;
};

// The call trace (tests: the checked and unchecked builds must issue the same
// Vulkan calls). While a sink is set, every Vulkan call runtime_vk makes is
// reported as one line: its name and its scalar arguments (handles and
// pointers as "h"/"0"), and the bytes it hands over (uploads, push
// constants) as a size and a hash. Not thread-safe; nullptr stops it.
void set_call_trace(std::function<void(std::string_view line)> sink);

}  // namespace safegi::vk
