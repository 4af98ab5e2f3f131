# Compiles one compile-fail case with -fsyntax-only.
#   MODE=fail   the program must not compile, and its first error must be on the user's
#               line: the first ': error: ' line starts with SOURCE's path and its message
#               is EXPECTED's line for this compiler ("g++: ..." or "clang++: ...") exactly.
#               A case whose mistake is a type computation, not a call (its EXPECTED has a
#               line "location: instantiation"), needs SOURCE named anywhere in the output
#               (the compilers' "required from here" / "requested here").
#   MODE=fixed  the program compiled with -DFIXED must build without warnings.
# Inputs: COMPILER, FLAVOUR (g++ or clang++), SOURCE, INCLUDES ('|'-separated), MODE, EXPECTED.
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
# The whole first error line: from the start of its line to its end.
string(SUBSTRING "${out}" 0 ${error_at} before_error)
string(FIND "${before_error}" "\n" line_start REVERSE)
math(EXPR line_start "${line_start} + 1")
string(SUBSTRING "${out}" ${line_start} -1 from_line)
string(FIND "${from_line}" "\n" line_end)
string(SUBSTRING "${from_line}" 0 ${line_end} first_error)
string(FIND "${first_error}" ": error: " message_at)
math(EXPR message_at "${message_at} + 9")
string(SUBSTRING "${first_error}" ${message_at} -1 message)

file(STRINGS "${EXPECTED}" expected_lines)
set(wanted "")
set(in_instantiation FALSE)
foreach(line IN LISTS expected_lines)
  if(line STREQUAL "location: instantiation")
    set(in_instantiation TRUE)
  endif()
  string(FIND "${line}" "${FLAVOUR}: " prefix_at)
  if(prefix_at EQUAL 0)
    string(LENGTH "${FLAVOUR}: " prefix_length)
    string(SUBSTRING "${line}" ${prefix_length} -1 wanted)
  endif()
endforeach()
if(wanted STREQUAL "")
  message(FATAL_ERROR "${EXPECTED} has no '${FLAVOUR}: ' line")
endif()

if(in_instantiation)
  string(FIND "${out}" "${SOURCE}:" user_at)
  if(user_at EQUAL -1)
    message(FATAL_ERROR "the output never names ${SOURCE}:\n${out}")
  endif()
else()
  string(FIND "${first_error}" "${SOURCE}:" user_at)
  if(NOT user_at EQUAL 0)
    message(FATAL_ERROR "the first error is not on the user's line (${SOURCE}):\n  ${first_error}")
  endif()
endif()
string(FIND "${message}" "${wanted}" found)
if(found EQUAL -1)
  message(FATAL_ERROR "expected the first error to say:\n  ${wanted}\nfound:\n  ${message}")
endif()
