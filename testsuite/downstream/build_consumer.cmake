# Installs this build into a scratch prefix, then configures, builds and runs
# project/ against that prefix only (CMAKE_PREFIX_PATH; no path into the
# build or source tree), and checks that the same project with a physics bug
# in its shader fails to build with safeglslc's diagnostic.
#   cmake -DBUILD=<build dir> -DPROJECT=<project dir> -DOUT=<scratch> -DGENERATOR=<gen> -DCXX=<c++> -P build_consumer.cmake
file(REMOVE_RECURSE ${OUT})
set(prefix ${OUT}/prefix)

function(step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${out}${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

step("cmake --install" ${CMAKE_COMMAND} --install ${BUILD} --prefix ${prefix})
set(configure ${CMAKE_COMMAND} -S ${PROJECT} -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)

step("configuring the consumer" ${configure} -B ${OUT}/good)
step("building the consumer" ${CMAKE_COMMAND} --build ${OUT}/good)
step("running the consumer" ${OUT}/good/downstream)
message(STATUS "${step_output}")
if(NOT step_output MATCHES "irradiance 0\\.0500 W/m\\^2")
  message(FATAL_ERROR "the consumer computed the wrong irradiance (expected 0.0500 W/m^2):\n${step_output}")
endif()

step("configuring the consumer with the buggy shader" ${configure} -B ${OUT}/bug -DDOWNSTREAM_WITH_BUG=ON)
execute_process(COMMAND ${CMAKE_COMMAND} --build ${OUT}/bug RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(status EQUAL 0)
  message(FATAL_ERROR "the consumer built although its shader forgets the cosine")
endif()
if(NOT "${out}${err}" MATCHES "emitter_missing_cosine\\.sgl\\.frag:13:18: error: .*missing cosine factor")
  message(FATAL_ERROR "the failed build does not show safeglslc's diagnostic:\n${out}${err}")
endif()
message(STATUS "the buggy shader fails the consumer's build with safeglslc's diagnostic")
