# Objects built checked and unchecked must not link together silently: the same
# declaration names safegi::checked:: types in one mode and safegi::unchecked:: types in
# the other, so the link fails with an undefined reference. Built in one mode, it links.
# Inputs: COMPILER, DIR (this folder), INCLUDES ('|'-separated), WORK_DIR.
string(REPLACE "|" ";" include_dirs "${INCLUDES}")
set(flags -std=c++20)
foreach(dir IN LISTS include_dirs)
  list(APPEND flags "-I${dir}")
endforeach()

foreach(unit IN ITEMS offset main)
  foreach(mode IN ITEMS 0 1)
    execute_process(COMMAND ${COMPILER} ${flags} -DSAFEGI_UNCHECKED=${mode} -c ${DIR}/${unit}.cpp
                            -o ${WORK_DIR}/${unit}.${mode}.o
                    RESULT_VARIABLE rc ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "compiling ${unit}.cpp (SAFEGI_UNCHECKED=${mode}) failed:\n${err}")
    endif()
  endforeach()
endforeach()

# Links offset() built in one mode with main() built in another.
function(build definition_mode main_mode out_result out_log)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env LC_ALL=C ${COMPILER} ${WORK_DIR}/offset.${definition_mode}.o
                          ${WORK_DIR}/main.${main_mode}.o -o ${WORK_DIR}/linked
                  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE err)
  set(${out_result} ${rc} PARENT_SCOPE)
  set(${out_log} "${err}" PARENT_SCOPE)
endfunction()

build(0 0 rc log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "checked objects do not link together:\n${log}")
endif()
build(1 1 rc log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "unchecked objects do not link together:\n${log}")
endif()
build(0 1 rc log)
if(rc EQUAL 0)
  message(FATAL_ERROR "a checked definition linked with an unchecked caller")
endif()
if(NOT log MATCHES "undefined reference to .offset\\(safegi::unchecked::")
  message(FATAL_ERROR "expected an undefined reference to the unchecked offset(), got:\n${log}")
endif()
message(STATUS "mixing modes fails to link, as it must:\n${log}")
