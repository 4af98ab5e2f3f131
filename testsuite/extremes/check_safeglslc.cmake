# Runs safeglslc on one shader and compares its exit status and its stderr with
# the expected ones exactly.
# Inputs: SAFEGLSLC, SHADER (as named in the diagnostics: run from its folder),
#         EXPECTED (file with the exact stderr), RC (expected exit status).
execute_process(COMMAND ${CMAKE_COMMAND} -E env NO_COLOR=1 ${SAFEGLSLC} --color=never ${SHADER}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(READ ${EXPECTED} expected)
if(NOT rc STREQUAL "${RC}")
  message(FATAL_ERROR "safeglslc ${SHADER}: exit status ${rc}, expected ${RC}; stderr:\n${err}")
endif()
if(NOT err STREQUAL expected)
  message(FATAL_ERROR "safeglslc ${SHADER}: diagnostics differ.\n--- expected\n${expected}--- found\n${err}")
endif()
