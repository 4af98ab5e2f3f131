#pragma once
// Typed handles (the paper's id<T>): a location that remembers the C++ type it
// was checked against, so only a value of that type can be given to it.
// Location -1 is a variable the driver optimized away: using it is a no-op,
// as in OpenGL.
#include <cstddef>
#include <type_traits>

// The unchecked build follows the typed library's switch unless told otherwise.
#ifndef SAFEGI_GL_UNCHECKED
#if defined(SAFEGI_UNCHECKED) && SAFEGI_UNCHECKED
#define SAFEGI_GL_UNCHECKED 1
#else
#define SAFEGI_GL_UNCHECKED 0
#endif
#endif

namespace safegi::gl {

// Which build this translation unit is: the checked API compares host types
// with the symbol table, the unchecked one only asks the driver. The mode is a
// template argument of every lookup so both builds never share an
// instantiation (no ODR clash if they meet in one program).
struct checked_mode {
  static constexpr bool checks = true;
};
struct unchecked_mode {
  static constexpr bool checks = false;
};
using build_mode = std::conditional_t<SAFEGI_GL_UNCHECKED != 0, unchecked_mode, checked_mode>;

template <class T>
struct uniform_id {
  int location = -1;
};

template <class T>
struct uniform_array_id {
  int location = -1;
  int size = 0;  // declared element count
};

template <class T>
struct attribute_id {
  int location = -1;
};

// A fragment output; T is the value one pixel of its attachment holds.
template <class T>
struct output_id {
  int location = -1;
};

// A sampler uniform; T is the texel type.
template <class T>
struct sampler_id {
  int location = -1;
};

// The paper's spelling.
template <class T>
using id = uniform_id<T>;

}  // namespace safegi::gl
