# Compiler flags shared by every SafeGI target.

if(SAFEGI_SANITIZE)
  # Debian's glslang is built without RTTI, so UBSan's vptr check cannot be used.
  set(SAFEGI_SANITIZER_FLAGS -fsanitize=address,undefined -fno-sanitize=vptr
                             -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  add_compile_options(${SAFEGI_SANITIZER_FLAGS})
  add_link_options(${SAFEGI_SANITIZER_FLAGS})
  # ASan's instrumentation makes GCC 12 report -Wmaybe-uninitialized inside
  # libstdc++'s <regex> and <functional>; the uninstrumented build keeps it on.
  add_compile_options(-Wno-maybe-uninitialized)
endif()

# Applies the project's warning level to one target without forcing it on
# third-party code pulled in through add_subdirectory.
function(safegi_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wno-missing-field-initializers)
  # GCC 12 reports false -Wrestrict positives inside libstdc++'s std::string
  # concatenation at -O2 (GCC bug 105329); the warning says nothing about our code.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
endfunction()
