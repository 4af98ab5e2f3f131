# Runs the checked and the unchecked build of trace_frame.cpp and fails unless
# they issued the same GL calls (and drew the same pixel).
#   cmake -DCHECKED=<exe> -DUNCHECKED=<exe> -DWORK_DIR=<dir> -P compare_traces.cmake
foreach(build CHECKED UNCHECKED)
  execute_process(COMMAND ${${build}} ${WORK_DIR}/${build}.trace
                  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${${build}} failed (${result}):\n${output}${error}")
  endif()
  message(STATUS "${output}")
endforeach()
file(READ ${WORK_DIR}/CHECKED.trace checked)
file(READ ${WORK_DIR}/UNCHECKED.trace unchecked)
if(NOT checked STREQUAL unchecked)
  execute_process(COMMAND diff -u ${WORK_DIR}/CHECKED.trace ${WORK_DIR}/UNCHECKED.trace OUTPUT_VARIABLE diff)
  message(FATAL_ERROR "the checked and unchecked builds issue different GL calls:\n${diff}")
endif()
string(REGEX MATCHALL "\n" lines "${checked}")
list(LENGTH lines count)
message(STATUS "identical GL call traces (${count} lines)")
