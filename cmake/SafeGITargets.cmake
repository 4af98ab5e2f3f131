# The shapes every part's CMakeLists.txt repeats, said once.

# safegi_add_library(<name> SOURCES <src>... [PUBLIC <dep>...] [PRIVATE <dep>...] [NO_INSTALL])
# Library safegi_<name> with the alias SafeGI::<name>, public headers from the
# folder's include/, the project's warnings, and (unless NO_INSTALL) installed
# into the SafeGI package with its headers.
function(safegi_add_library name)
  cmake_parse_arguments(ARG "NO_INSTALL" "" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  set(target safegi_${name})
  add_library(${target} ${ARG_SOURCES})
  add_library(SafeGI::${name} ALIAS ${target})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_link_libraries(${target} PUBLIC ${ARG_PUBLIC} PRIVATE ${ARG_PRIVATE})
  safegi_target_defaults(${target})
  if(NOT ARG_NO_INSTALL)
    safegi_install_targets(${target} HEADERS_FROM ${CMAKE_CURRENT_SOURCE_DIR}/include)
  endif()
endfunction()

# safegi_test_defaults(<target>): the project's warnings for a test program,
# whose own code is compiled at -O1 in Release. What a test checks is compiled
# by the libraries it links, at the build's level (-O3); the test bodies only
# call them, and -O3 over GoogleTest's expansions and nlohmann::json literals
# cost 489 of the Release build's 1164 CPU-seconds (about 370 at -O1; the
# build is CI's largest cost).
function(safegi_test_defaults target)
  safegi_target_defaults(${target})
  target_compile_options(${target} PRIVATE $<$<CONFIG:Release>:-O1>)
endfunction()

# safegi_add_gtest(<exe> SOURCES <src>... LIBS <lib>... [LABEL <label>])
# A GoogleTest executable (gtest_main linked) whose tests ctest discovers.
# LABEL `sanitize` means CI reruns them under ASan+UBSan, so give it only to
# tests that need neither GL nor OpenImageIO. One label only: CMake 3.25's
# gtest_discover_tests writes a list of labels unquoted, so every label after
# the first is lost; a folder-wide label goes on the directory instead
# (set_property(DIRECTORY APPEND PROPERTY LABELS <name>)).
function(safegi_add_gtest exe)
  cmake_parse_arguments(ARG "" "LABEL" "SOURCES;LIBS" ${ARGN})
  add_executable(${exe} ${ARG_SOURCES})
  target_link_libraries(${exe} PRIVATE ${ARG_LIBS} GTest::gtest_main)
  safegi_test_defaults(${exe})
  if(ARG_LABEL)
    gtest_discover_tests(${exe} PROPERTIES LABELS ${ARG_LABEL})
  else()
    gtest_discover_tests(${exe})
  endif()
endfunction()

# Adds every subfolder that has a CMakeLists.txt, in name order: the folders
# that only collect parts (bench/, examples/, testsuite/) call this.
macro(safegi_add_subfolders)
  file(GLOB _safegi_children LIST_DIRECTORIES true RELATIVE ${CMAKE_CURRENT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR}/*)
  list(SORT _safegi_children)
  foreach(_safegi_child IN LISTS _safegi_children)
    if(IS_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/${_safegi_child}
       AND EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${_safegi_child}/CMakeLists.txt)
      add_subdirectory(${_safegi_child})
    endif()
  endforeach()
endmacro()
