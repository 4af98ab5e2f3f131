# The symbol-table contract's example program (symbol_table/testdata), read by
# symbol_table's and runtime_gl's tests: its GLSL and symbol tables must be what
# safeglslc writes for the annotated sources beside them, so the hosts are tested
# against the real compiler.
#   cmake -DSAFEGLSLC=<exe> -DTESTDATA=<dir> -DOUT=<scratch dir> -P compare_fixture.cmake
file(MAKE_DIRECTORY ${OUT})
function(compile_and_compare)
  cmake_parse_arguments(ARG "" "SYMBOLS" "SOURCES;GLSL" ${ARGN})
  set(args ${ARG_SOURCES})
  foreach(glsl IN LISTS ARG_GLSL)
    list(APPEND args -o ${OUT}/${glsl})
  endforeach()
  execute_process(COMMAND ${SAFEGLSLC} ${args} --symbols ${OUT}/${ARG_SYMBOLS}
                  WORKING_DIRECTORY ${TESTDATA} RESULT_VARIABLE status ERROR_VARIABLE errors)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "safeglslc ${ARG_SOURCES} failed:\n${errors}")
  endif()
  foreach(file IN LISTS ARG_GLSL ARG_SYMBOLS)
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${TESTDATA}/${file} ${OUT}/${file} RESULT_VARIABLE differs)
    if(differs)
      execute_process(COMMAND diff -u ${TESTDATA}/${file} ${OUT}/${file} OUTPUT_VARIABLE difference)
      message(SEND_ERROR "${TESTDATA}/${file} is not what safeglslc writes for ${ARG_SOURCES} "
                         "(regenerate it with the same command in that folder):\n${difference}")
    endif()
  endforeach()
endfunction()
compile_and_compare(SOURCES emission.sgl.vert GLSL emission.vert.glsl SYMBOLS emission.vert.json)
compile_and_compare(SOURCES emission.sgl.frag GLSL emission.frag.glsl SYMBOLS emission.frag.json)
compile_and_compare(SOURCES emission.sgl.vert emission.sgl.frag SYMBOLS emission.program.json)
