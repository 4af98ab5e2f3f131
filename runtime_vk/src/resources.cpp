#include "safegi/runtime_vk/resources.hpp"

#include <cstring>

#include "calls.hpp"
#include "context_impl.hpp"

namespace safegi::vk::detail {
namespace {

constexpr const VkAllocationCallbacks* kNoAllocator = nullptr;

VkFormat format_of(ScalarType scalar, int components) {
  static constexpr VkFormat floats[] = {VK_FORMAT_R32_SFLOAT, VK_FORMAT_R32G32_SFLOAT, VK_FORMAT_UNDEFINED,
                                        VK_FORMAT_R32G32B32A32_SFLOAT};
  static constexpr VkFormat ints[] = {VK_FORMAT_R32_SINT, VK_FORMAT_R32G32_SINT, VK_FORMAT_UNDEFINED,
                                      VK_FORMAT_R32G32B32A32_SINT};
  static constexpr VkFormat uints[] = {VK_FORMAT_R32_UINT, VK_FORMAT_R32G32_UINT, VK_FORMAT_UNDEFINED,
                                       VK_FORMAT_R32G32B32A32_UINT};
  const VkFormat* table = scalar == ScalarType::float32 ? floats : scalar == ScalarType::int32 ? ints : uints;
  return table[components - 1];
}

VkDeviceMemory allocate(ContextImpl& context, VkMemoryRequirements requirements, VkMemoryPropertyFlags flags) {
  auto allocate = make<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
  allocate.allocationSize = requirements.size;
  allocate.memoryTypeIndex = context.memory_type(requirements.memoryTypeBits, flags);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  check(SAFEGI_VK(vkAllocateMemory, context.device, &allocate, kNoAllocator, &memory), "vkAllocateMemory");
  return memory;
}

void transition(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                VkAccessFlags from_access, VkAccessFlags to_access, VkPipelineStageFlags from_stage,
                VkPipelineStageFlags to_stage);

}  // namespace

[[noreturn]] void throw_wrong_block(const std::string& data_name, std::uint32_t expected, std::uint32_t found) {
  throw BindingError("safegi::vk: block '" + data_name + "' (symbol " + std::to_string(expected) +
                     ") used through a handle of another block (symbol " + std::to_string(found) +
                     "); look the handle up in the pipeline and block the data was made for");
}

[[noreturn]] void throw_out_of_range(const std::string& what, std::size_t end, std::size_t size) {
  throw ResourceError("safegi::vk: " + what + " reaches byte " + std::to_string(end) + ", past the " +
                      std::to_string(size) + " there are");
}

Buffer::Buffer(ContextImpl& context, std::size_t bytes, BufferUse use) : context_(&context), size_(bytes), use_(use) {
  auto create = make<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
  create.size = bytes == 0 ? 16 : bytes;  // Vulkan has no empty buffer
  create.usage = (use == BufferUse::uniform ? VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT : VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) |
                 VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  create.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  check(SAFEGI_VK(vkCreateBuffer, context_->device, &create, kNoAllocator, &buffer_), "vkCreateBuffer");
  try {
    VkMemoryRequirements requirements;
    SAFEGI_VK(vkGetBufferMemoryRequirements, context_->device, buffer_, &requirements);
    memory_ =
        allocate(*context_, requirements, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    check(SAFEGI_VK(vkBindBufferMemory, context_->device, buffer_, memory_, VkDeviceSize{0}), "vkBindBufferMemory");
    void* mapped = nullptr;
    check(SAFEGI_VK(vkMapMemory, context_->device, memory_, VkDeviceSize{0}, VkDeviceSize{VK_WHOLE_SIZE},
                    VkMemoryMapFlags{0}, &mapped),
          "vkMapMemory");
    mapped_ = static_cast<std::byte*>(mapped);
    std::memset(mapped_, 0, size_);
  } catch (...) {
    release();
    throw;
  }
}

Buffer::~Buffer() { release(); }

Buffer::Buffer(Buffer&& other) noexcept
    : context_(other.context_),
      buffer_(std::exchange(other.buffer_, VK_NULL_HANDLE)),
      memory_(std::exchange(other.memory_, VK_NULL_HANDLE)),
      mapped_(std::exchange(other.mapped_, nullptr)),
      size_(other.size_),
      use_(other.use_) {}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    release();
    context_ = other.context_;
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    mapped_ = std::exchange(other.mapped_, nullptr);
    size_ = other.size_;
    use_ = other.use_;
  }
  return *this;
}

void Buffer::release() noexcept {
  if (!context_) return;
  if (buffer_) SAFEGI_VK(vkDestroyBuffer, context_->device, buffer_, kNoAllocator);
  if (memory_) SAFEGI_VK(vkFreeMemory, context_->device, memory_, kNoAllocator);  // unmaps
  buffer_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  mapped_ = nullptr;
}

void Buffer::write(std::size_t offset, std::span<const std::byte> bytes) {
  if (offset + bytes.size() > size_) throw_out_of_range("a write to the buffer", offset + bytes.size(), size_);
  trace_bytes("upload", bytes);
  if (!bytes.empty()) std::memcpy(mapped_ + offset, bytes.data(), bytes.size());
}

void Buffer::read(std::size_t offset, std::span<std::byte> bytes) const {
  if (offset + bytes.size() > size_) throw_out_of_range("a read from the buffer", offset + bytes.size(), size_);
  if (!bytes.empty()) std::memcpy(bytes.data(), mapped_ + offset, bytes.size());
}

Image::Image(Context& context, int width, int height, ScalarType scalar, int components)
    : context_(&context.impl()), width_(width), height_(height), texel_bytes_(4u * static_cast<unsigned>(components)) {
  if (width <= 0 || height <= 0)
    throw ResourceError("safegi::vk: an image of " + std::to_string(width) + 'x' + std::to_string(height) + " texels");
  const VkFormat format = format_of(scalar, components);
  auto create = make<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
  create.imageType = VK_IMAGE_TYPE_2D;
  create.format = format;
  create.extent = {static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height), 1};
  create.mipLevels = 1;
  create.arrayLayers = 1;
  create.samples = VK_SAMPLE_COUNT_1_BIT;
  create.tiling = VK_IMAGE_TILING_OPTIMAL;
  create.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  create.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  create.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  check(SAFEGI_VK(vkCreateImage, context_->device, &create, kNoAllocator, &image_), "vkCreateImage");
  try {
    VkMemoryRequirements requirements;
    SAFEGI_VK(vkGetImageMemoryRequirements, context_->device, image_, &requirements);
    memory_ = allocate(*context_, requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    check(SAFEGI_VK(vkBindImageMemory, context_->device, image_, memory_, VkDeviceSize{0}), "vkBindImageMemory");
    auto view = make<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
    view.image = image_;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format;
    view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    check(SAFEGI_VK(vkCreateImageView, context_->device, &view, kNoAllocator, &view_), "vkCreateImageView");
    // Cleared to zero, then GENERAL between uses (what storage images need).
    context_->submit([&](VkCommandBuffer commands) {
      transition(commands, image_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
                 VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
      const VkClearColorValue zero{};
      SAFEGI_VK(vkCmdClearColorImage, commands, image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1u,
                &view.subresourceRange);
      transition(commands, image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                 VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
    });
  } catch (...) {
    release();
    throw;
  }
}

Image::~Image() { release(); }

Image::Image(Image&& other) noexcept
    : context_(other.context_),
      image_(std::exchange(other.image_, VK_NULL_HANDLE)),
      memory_(std::exchange(other.memory_, VK_NULL_HANDLE)),
      view_(std::exchange(other.view_, VK_NULL_HANDLE)),
      width_(other.width_),
      height_(other.height_),
      texel_bytes_(other.texel_bytes_) {}

Image& Image::operator=(Image&& other) noexcept {
  if (this != &other) {
    release();
    context_ = other.context_;
    image_ = std::exchange(other.image_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    view_ = std::exchange(other.view_, VK_NULL_HANDLE);
    width_ = other.width_;
    height_ = other.height_;
    texel_bytes_ = other.texel_bytes_;
  }
  return *this;
}

void Image::release() noexcept {
  if (!context_) return;
  if (view_) SAFEGI_VK(vkDestroyImageView, context_->device, view_, kNoAllocator);
  if (image_) SAFEGI_VK(vkDestroyImage, context_->device, image_, kNoAllocator);
  if (memory_) SAFEGI_VK(vkFreeMemory, context_->device, memory_, kNoAllocator);
  view_ = VK_NULL_HANDLE;
  image_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
}

namespace {

// Moves the whole image from one layout to another, ordering `from_access`
// work in `from_stage` before `to_access` work in `to_stage`.
void transition(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                VkAccessFlags from_access, VkAccessFlags to_access, VkPipelineStageFlags from_stage,
                VkPipelineStageFlags to_stage) {
  auto barrier = make<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
  barrier.srcAccessMask = from_access;
  barrier.dstAccessMask = to_access;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  SAFEGI_VK(vkCmdPipelineBarrier, commands, from_stage, to_stage, VkDependencyFlags{0}, 0u,
            static_cast<const VkMemoryBarrier*>(nullptr), 0u, static_cast<const VkBufferMemoryBarrier*>(nullptr), 1u,
            static_cast<const VkImageMemoryBarrier*>(&barrier));
}

// Copies between the image (GENERAL between uses, a transfer layout during the
// copy) and a buffer; `to_image` says which way.
void copy(ContextImpl& context, VkImage image, VkBuffer buffer, int width, int height, bool to_image) {
  const VkImageLayout during = to_image ? VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  const VkAccessFlags transfer = to_image ? VK_ACCESS_TRANSFER_WRITE_BIT : VK_ACCESS_TRANSFER_READ_BIT;
  context.submit([&](VkCommandBuffer commands) {
    transition(commands, image, VK_IMAGE_LAYOUT_GENERAL, during,
               VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT, transfer,
               VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height), 1};
    if (to_image)
      SAFEGI_VK(vkCmdCopyBufferToImage, commands, buffer, image, during, 1u,
                static_cast<const VkBufferImageCopy*>(&region));
    else
      SAFEGI_VK(vkCmdCopyImageToBuffer, commands, image, during, buffer, 1u,
                static_cast<const VkBufferImageCopy*>(&region));
    transition(commands, image, during, VK_IMAGE_LAYOUT_GENERAL, transfer,
               VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
               VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
    if (!to_image) {  // the host reads the buffer next
      auto host = make<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
      host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
      host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
      SAFEGI_VK(vkCmdPipelineBarrier, commands, VkPipelineStageFlags{VK_PIPELINE_STAGE_TRANSFER_BIT},
                VkPipelineStageFlags{VK_PIPELINE_STAGE_HOST_BIT}, VkDependencyFlags{0}, 1u,
                static_cast<const VkMemoryBarrier*>(&host), 0u, static_cast<const VkBufferMemoryBarrier*>(nullptr), 0u,
                static_cast<const VkImageMemoryBarrier*>(nullptr));
    }
  });
}

}  // namespace

void Image::upload(std::span<const std::byte> texels) {
  const std::size_t size = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * texel_bytes_;
  if (texels.size() != size) throw_out_of_range("an image upload", texels.size(), size);
  Buffer staging(*context_, size, BufferUse::storage);
  staging.write(0, texels);
  copy(*context_, image_, staging.handle(), width_, height_, true);
}

void Image::read(std::span<std::byte> texels) const {
  const std::size_t size = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * texel_bytes_;
  if (texels.size() != size) throw_out_of_range("an image read", texels.size(), size);
  Buffer staging(*context_, size, BufferUse::storage);
  copy(*context_, image_, staging.handle(), width_, height_, false);
  staging.read(0, texels);
}

}  // namespace safegi::vk::detail
