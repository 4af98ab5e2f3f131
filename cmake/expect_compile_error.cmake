# Compiles SOURCE and passes only when the compiler rejects it with output
# matching EXPECT.
#   cmake -DCOMPILER=<c++> -DFLAGS=<list> -DSOURCE=<file> -DEXPECT=<regex> -P expect_compile_error.cmake
execute_process(COMMAND ${COMPILER} ${FLAGS} -fsyntax-only ${SOURCE}
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(result EQUAL 0)
  message(FATAL_ERROR "${SOURCE} compiled, but must not")
endif()
if(NOT output MATCHES "${EXPECT}")
  message(FATAL_ERROR "${SOURCE} failed without the expected error '${EXPECT}':\n${output}")
endif()
message(STATUS "rejected as expected")
