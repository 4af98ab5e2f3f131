# Runs the checked and the unchecked build of one trace program (runtime_gl's
# trace_frame.cpp, runtime_vk's trace_dispatch.cpp) and fails unless they
# issued the same API calls (and computed the same result).
#   cmake -DCHECKED=<exe> -DUNCHECKED=<exe> -DWORK_DIR=<dir> [-DAPI=GL|Vulkan] -P compare_traces.cmake
if(NOT API)
  set(API GL)
endif()
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
  message(FATAL_ERROR "the checked and unchecked builds issue different ${API} calls:\n${diff}")
endif()
string(REGEX MATCHALL "\n" lines "${checked}")
list(LENGTH lines count)
message(STATUS "identical ${API} call traces (${count} lines)")
