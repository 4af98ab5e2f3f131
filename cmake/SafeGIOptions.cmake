# Compiler flags shared by every SafeGI target.

if(SAFEGI_SANITIZE)
  # Debian's glslang is built without RTTI, so UBSan's vptr check cannot be used.
  set(SAFEGI_SANITIZER_FLAGS -fsanitize=address,undefined -fno-sanitize=vptr
                             -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  add_compile_options(${SAFEGI_SANITIZER_FLAGS})
  add_link_options(${SAFEGI_SANITIZER_FLAGS})
  # ASan's instrumentation makes GCC 12 report -Wmaybe-uninitialized inside
  # libstdc++'s <regex> and <functional>; the uninstrumented build keeps it on.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    add_compile_options(-Wno-maybe-uninitialized)
  endif()
endif()

# Applies the project's warning level to one target without forcing it on
# third-party code pulled in through add_subdirectory.
function(safegi_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wno-missing-field-initializers)
  # The build has no warning under GCC 12 and Clang 14; CI keeps it so (SAFEGI_WERROR=ON).
  # Off by default, so a newer compiler's new warning never stops a user's build.
  if(SAFEGI_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  safegi_precompile_common_headers(${target})
  # GCC 12 reports false -Wrestrict positives inside libstdc++'s std::string
  # concatenation at -O2 (GCC bug 105329); the warning says nothing about our code.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
endfunction()

# safegi_precompile_common_headers(<target>): the standard library headers
# nearly every source here includes, and GoogleTest for a test program, parsed
# once per target instead of once per source. Parsing them was about a third
# of each compile (CI's largest cost is the two builds). Only for targets of
# several sources: for one source the header would be parsed once anyway.
function(safegi_precompile_common_headers target)
  if(NOT SAFEGI_PRECOMPILE_HEADERS)
    return()
  endif()
  get_target_property(sources ${target} SOURCES)
  # C++ only: a precompiled header would also be made for C sources (runtime_gl's GL loader).
  if(sources MATCHES "\\.c(;|$)")
    return()
  endif()
  list(FILTER sources INCLUDE REGEX "\\.cpp$")
  list(LENGTH sources count)
  if(count LESS 3)
    return()
  endif()
  set(headers ${PROJECT_SOURCE_DIR}/cmake/precompiled/common.hpp)
  get_target_property(libraries ${target} LINK_LIBRARIES)
  if(libraries MATCHES "GTest::")
    list(APPEND headers ${PROJECT_SOURCE_DIR}/cmake/precompiled/gtest.hpp)
  endif()
  target_precompile_headers(${target} PRIVATE ${headers})
  # With libstdc++'s <string> precompiled, GCC 12 reports false -Wstringop-overflow
  # and -Warray-bounds positives inside std::string's operator+ (as with -Wrestrict
  # above; -Warray-bounds: "pointer overflow between offset [2, …]" in char_traits.h).
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-stringop-overflow -Wno-array-bounds)
  endif()
endfunction()
