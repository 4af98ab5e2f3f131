#pragma once
// Typed handles: where a name of the shader's interface lives (descriptor set
// and binding, byte offset in a block), looked up once through the symbol
// table and remembering the C++ type it was checked against, so only a value
// or resource of that type can be given to it (anything else does not compile).
#include <cstdint>
#include <type_traits>

// The unchecked build follows the typed library's switch unless told otherwise.
#ifndef SAFEGI_VK_UNCHECKED
#if defined(SAFEGI_UNCHECKED) && SAFEGI_UNCHECKED
#define SAFEGI_VK_UNCHECKED 1
#else
#define SAFEGI_VK_UNCHECKED 0
#endif
#endif

namespace safegi::vk {

// Which build this translation unit is: the checked one compares host types
// with the symbol table; the unchecked one only reads where things are. The
// mode is a template argument of every lookup, so a checked and an unchecked
// object file never share an instantiation.
struct checked_mode {
  static constexpr bool checks = true;
};
struct unchecked_mode {
  static constexpr bool checks = false;
};
using build_mode = std::conditional_t<SAFEGI_VK_UNCHECKED != 0, unchecked_mode, checked_mode>;

struct descriptor_slot {
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
};

// A member of a block (push constants, a uniform or storage block) holding a T.
template <class T>
struct member_id {
  std::uint32_t offset = 0;
  std::uint32_t matrix_stride = 0;  // matrices: bytes from one column to the next
  std::uint32_t block = 0;          // which block of the pipeline (checked by block_data)
};

// An array member of a block: `count` elements of T, `stride` bytes apart
// (count 0: runtime-sized, as many as the buffer holds).
template <class T>
struct array_member_id {
  std::uint32_t offset = 0;
  std::uint32_t stride = 0;
  std::uint32_t count = 0;
  std::uint32_t matrix_stride = 0;
  std::uint32_t block = 0;
};

// A whole uniform or storage block, bound from a block_buffer.
struct block_binding_id {
  descriptor_slot slot;
  std::uint32_t block = 0;
};

// A storage block that is one array of T (the block's only member, at offset
// 0), bound from a storage_buffer<T>.
template <class T>
struct storage_array_id {
  descriptor_slot slot;
  std::uint32_t stride = 0;
};

// A storage image whose texels are T, bound from an image2d<T>.
template <class T>
struct image_id {
  descriptor_slot slot;
};

}  // namespace safegi::vk
