# Compiles one compile-fail case with -fsyntax-only.
#   MODE=fail   the program must not compile; the first error line must contain the
#               first line of EXPECTED, and every further line of EXPECTED must appear
#               in what g++ prints up to that first error (the "In instantiation of"
#               lines that name both sides in words).
#   MODE=fixed  the program compiled with -DFIXED must build without warnings.
# Inputs: COMPILER, SOURCE, INCLUDES ('|'-separated), MODE, EXPECTED.
string(REPLACE "|" ";" include_dirs "${INCLUDES}")
set(flags -std=c++20 -fsyntax-only -fdiagnostics-color=never)
foreach(dir IN LISTS include_dirs)
  list(APPEND flags "-I${dir}")
endforeach()
if(MODE STREQUAL "fixed")
  list(APPEND flags -DFIXED -Wall -Wextra -Wpedantic -Werror -Wno-unused-parameter)
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env LC_ALL=C ${COMPILER} ${flags} ${SOURCE}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)

if(MODE STREQUAL "fixed")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the fixed program does not compile cleanly:\n${out}")
  endif()
  return()
endif()

if(rc EQUAL 0)
  message(FATAL_ERROR "${SOURCE} compiled, but the mistake in it must be rejected")
endif()
string(FIND "${out}" ": error: " error_at)
if(error_at EQUAL -1)
  message(FATAL_ERROR "the compiler failed without an error line:\n${out}")
endif()
string(SUBSTRING "${out}" ${error_at} -1 from_error)
string(FIND "${from_error}" "\n" line_end)
string(SUBSTRING "${from_error}" 0 ${line_end} first_error)
math(EXPR prefix_length "${error_at} + ${line_end}")
string(SUBSTRING "${out}" 0 ${prefix_length} first_lines)

# Expected lines may contain ';', which CMake lists would split on.
file(READ "${EXPECTED}" expected)
string(REPLACE ";" "<semicolon>" expected "${expected}")
string(REGEX REPLACE "\n$" "" expected "${expected}")
string(REPLACE "\n" ";" expected_lines "${expected}")
set(index 0)
foreach(line IN LISTS expected_lines)
  string(REPLACE "<semicolon>" ";" line "${line}")
  if(index EQUAL 0)
    string(FIND "${first_error}" "${line}" found)
    set(where "the first error line")
    set(searched "${first_error}")
  else()
    string(FIND "${first_lines}" "${line}" found)
    set(where "the lines up to the first error")
    set(searched "${first_lines}")
  endif()
  if(found EQUAL -1)
    message(FATAL_ERROR "expected in ${where}:\n  ${line}\nfound:\n${searched}")
  endif()
  math(EXPR index "${index} + 1")
endforeach()
