# Renders SCENE with the typed and the unchecked preview programs and requires
# identical pixels (PFM files: the EXR header carries a time stamp).
file(MAKE_DIRECTORY ${OUT})
foreach(program IN ITEMS TYPED UNCHECKED)
  execute_process(COMMAND ${${program}} ${SCENE} -o ${OUT}/${program}.exr --pfm --resolution 96x40 --light-samples 4
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${${program}} failed (${rc}): ${err}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/TYPED.pfm ${OUT}/UNCHECKED.pfm RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "the typed and unchecked previews of ${SCENE} differ")
endif()
