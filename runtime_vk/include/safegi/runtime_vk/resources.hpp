#pragma once
// Typed Vulkan resources: host-visible buffers (a block's bytes, or an array
// of T with the std430 stride), 2D storage images of T, and block_data, the
// bytes of one block (push constants, a uniform or storage block) written
// member by member through typed handles. Each owns its Vulkan objects
// (RAII, move-only); the Context must outlive them.
#include <vulkan/vulkan_core.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "safegi/runtime_vk/context.hpp"
#include "safegi/runtime_vk/handles.hpp"
#include "safegi/runtime_vk/layout.hpp"

namespace safegi::vk {

enum class BufferUse { storage, uniform };

namespace detail {

// One VkBuffer in host-visible, coherent memory, mapped for its lifetime.
class Buffer {
 public:
  Buffer(ContextImpl& context, std::size_t bytes, BufferUse use);
  Buffer(Context& context, std::size_t bytes, BufferUse use) : Buffer(context.impl(), bytes, use) {}
  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  // Throws ResourceError when the range is outside the buffer.
  void write(std::size_t offset, std::span<const std::byte> bytes);
  void read(std::size_t offset, std::span<std::byte> bytes) const;
  std::size_t size() const { return size_; }
  BufferUse use() const { return use_; }
  VkBuffer handle() const { return buffer_; }

 private:
  void release() noexcept;
  ContextImpl* context_ = nullptr;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  std::byte* mapped_ = nullptr;
  std::size_t size_ = 0;
  BufferUse use_ = BufferUse::storage;
};

// One VkImage (2D, VK_IMAGE_LAYOUT_GENERAL, usable as a storage image) and its view.
class Image {
 public:
  Image(Context& context, int width, int height, ScalarType scalar, int components);
  ~Image();
  Image(Image&& other) noexcept;
  Image& operator=(Image&& other) noexcept;
  Image(const Image&) = delete;
  Image& operator=(const Image&) = delete;

  // Whole image, rows from the top, texels of `texel_bytes` packed.
  void upload(std::span<const std::byte> texels);
  void read(std::span<std::byte> texels) const;
  VkImageView view() const { return view_; }
  VkImage handle() const { return image_; }
  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t texel_bytes() const { return texel_bytes_; }

 private:
  void release() noexcept;
  ContextImpl* context_ = nullptr;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  int width_ = 0, height_ = 0;
  std::size_t texel_bytes_ = 0;
};

[[noreturn]] void throw_wrong_block(const std::string& data_name, std::uint32_t expected, std::uint32_t found);
[[noreturn]] void throw_out_of_range(const std::string& what, std::size_t end, std::size_t size);

}  // namespace detail

// The bytes of one block as the symbol table lays it out: made by a pipeline
// (push_constants(), block(name)), written through member handles of the
// same pipeline and block.
class block_data {
 public:
  block_data(std::string name, std::uint32_t block, std::size_t size, BufferUse use)
      : name_(std::move(name)), block_(block), bytes_(size), use_(use) {}

  template <buffer_element T>
  void set(member_id<T> member, const T& value) {
    check(member.block, member.offset, detail::value_size<T>(member.matrix_stride));
    detail::encode(bytes_.data() + member.offset, value, member.matrix_stride);
  }
  // Writes values[0..n) to elements 0..n of the array (n at most its count).
  template <buffer_element T>
  void set(array_member_id<T> member, std::type_identity_t<std::span<const T>> values) {
    if (member.count != 0 && values.size() > member.count)
      throw ResourceError("safegi::vk: block '" + name_ + "': " + std::to_string(values.size()) +
                          " values for an array of " + std::to_string(member.count));
    check(member.block, member.offset, values.size() * member.stride);
    for (std::size_t i = 0; i < values.size(); ++i)
      detail::encode(bytes_.data() + member.offset + i * member.stride, values[i], member.matrix_stride);
  }
  template <readable_element T>
  T get(member_id<T> member) const {
    check(member.block, member.offset, detail::value_size<T>(member.matrix_stride));
    return detail::decode<T>(bytes_.data() + member.offset, member.matrix_stride);
  }
  template <readable_element T>
  T get(array_member_id<T> member, std::size_t index) const {
    check(member.block, member.offset, (index + 1) * member.stride);
    return detail::decode<T>(bytes_.data() + member.offset + index * member.stride, member.matrix_stride);
  }

  // Copies a host struct that mirrors the block byte for byte (check it
  // against a generated header's layout:: with SAFEGI_VK_EXPECT_MEMBER).
  template <class Host>
  requires std::is_trivially_copyable_v<Host>
  void copy_from(const Host& host) {
    if (sizeof(Host) > bytes_.size())
      detail::throw_out_of_range("block '" + name_ + "': a host struct", sizeof(Host), bytes_.size());
    std::memcpy(bytes_.data(), &host, sizeof(Host));
  }

  const std::string& name() const { return name_; }
  std::uint32_t block() const { return block_; }
  BufferUse use() const { return use_; }
  std::span<const std::byte> bytes() const { return bytes_; }
  std::span<std::byte> bytes() { return bytes_; }

 private:
  void check(std::uint32_t block, std::size_t offset, std::size_t size) const {
    if (block != block_) detail::throw_wrong_block(name_, block_, block);
    if (offset + size > bytes_.size())
      detail::throw_out_of_range("block '" + name_ + "': a write or read", offset + size, bytes_.size());
  }
  std::string name_;
  std::uint32_t block_;
  std::vector<std::byte> bytes_;
  BufferUse use_;
};

// A buffer holding one block (uniform or storage, as its block_data says).
class block_buffer {
 public:
  block_buffer(Context& context, const block_data& data)
      : buffer_(context, data.bytes().size(), data.use()), block_(data.block()) {
    update(data);
  }
  void update(const block_data& data) {
    if (data.block() != block_) detail::throw_wrong_block(data.name(), block_, data.block());
    buffer_.write(0, data.bytes());
  }
  // Reads the buffer into `data` (a storage block the shader wrote).
  void read(block_data& data) const {
    if (data.block() != block_) detail::throw_wrong_block(data.name(), block_, data.block());
    buffer_.read(0, data.bytes());
  }
  std::uint32_t block() const { return block_; }
  const detail::Buffer& raw() const { return buffer_; }

 private:
  detail::Buffer buffer_;
  std::uint32_t block_;
};

// A storage buffer holding an array of T with the std430 stride (a
// spectrum<radiance> takes 16 bytes, a host_struct sizeof(T)).
template <buffer_element T>
class storage_buffer {
 public:
  static constexpr std::uint32_t stride = detail::std430_stride<T>();

  storage_buffer(Context& context, std::size_t count)
      : buffer_(context, (count == 0 ? 1 : count) * stride, BufferUse::storage), count_(count) {}
  storage_buffer(Context& context, std::span<const T> values) : storage_buffer(context, values.size()) {
    upload(values);
  }

  // Replaces elements [0, values.size()).
  void upload(std::span<const T> values) {
    if (values.size() > count_)
      detail::throw_out_of_range("storage_buffer: an upload of " + std::to_string(values.size()) + " elements",
                                 values.size() * stride, count_ * stride);
    std::vector<std::byte> bytes(values.size() * stride);
    for (std::size_t i = 0; i < values.size(); ++i) detail::encode(bytes.data() + i * stride, values[i], 16);
    buffer_.write(0, bytes);
  }
  std::vector<T> read_back() const requires readable_element<T> {
    std::vector<std::byte> bytes(count_ * stride);
    buffer_.read(0, bytes);
    std::vector<T> values;
    values.reserve(count_);
    for (std::size_t i = 0; i < count_; ++i) values.push_back(detail::decode<T>(bytes.data() + i * stride, 16));
    return values;
  }
  std::size_t size() const { return count_; }
  const detail::Buffer& raw() const { return buffer_; }

 private:
  detail::Buffer buffer_;
  std::size_t count_;
};

// A 2D storage image of T: float, vec2, vec4 (r32f, rg32f, rgba32f) and
// their int/uint twins, or a typed value whose representation is one of
// them. Three components have no storage format: use a vec4.
template <gl_storable T>
class image2d {
  static_assert(gl_layout_of<T>::columns == 1 && gl_layout_of<T>::components != 3,
                "a storage image texel is 1, 2 or 4 components (rgb32f is no storage format: use a vec4)");

 public:
  image2d(Context& context, int width, int height)
      : image_(context, width, height, gl_layout_of<T>::scalar, gl_layout_of<T>::components) {}
  image2d(Context& context, int width, int height, std::span<const T> texels) : image2d(context, width, height) {
    upload(texels);
  }

  // Every texel, rows from the top (image coordinates: y = 0 first).
  void upload(std::span<const T> texels) {
    check_count(texels.size());
    std::vector<gl_type_of<T>> data;
    data.reserve(texels.size());
    for (const T& t : texels) data.push_back(value_traits<T>::to_gl(t));
    image_.upload(std::as_bytes(std::span(data)));
  }
  std::vector<T> read_back() const {
    std::vector<gl_type_of<T>> data(texel_count());
    image_.read(std::as_writable_bytes(std::span(data)));
    std::vector<T> texels;
    texels.reserve(data.size());
    for (const auto& d : data) texels.push_back(value_traits<T>::from_gl(d));
    return texels;
  }
  int width() const { return image_.width(); }
  int height() const { return image_.height(); }
  const detail::Image& raw() const { return image_; }

 private:
  std::size_t texel_count() const {
    return static_cast<std::size_t>(image_.width()) * static_cast<std::size_t>(image_.height());
  }
  void check_count(std::size_t count) const {
    if (count != texel_count())
      throw ResourceError("safegi::vk: image2d upload of " + std::to_string(count) + " texels into a " +
                          std::to_string(width()) + 'x' + std::to_string(height()) + " image");
  }
  detail::Image image_;
};

}  // namespace safegi::vk
