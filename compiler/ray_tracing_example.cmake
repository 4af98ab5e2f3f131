# The annotated ray-tracing pipeline of examples/shaders/ray_tracing/: checked
# as one program (the hit and miss payloads against the ray generation
# shader's), each stage compiled with -V --target-env vulkan1.2 to a module
# spirv-val accepts, alone and in one program run; and the closest-hit shader with the area pdf left in the
# area measure (the classic Jacobian bug) is refused.
#   cmake -DSAFEGLSLC=<exe> -DSPIRV_VAL=<spirv-val> -DDIR=<example dir> -DOUT=<scratch dir> -P ray_tracing_example.cmake
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
set(stages direct.sgl.rgen direct.sgl.rchit direct.sgl.rmiss direct_shadow.sgl.rmiss)

function(run expect_success)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${DIR} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(REPLACE ";" " " command "${ARGN}")
  if(expect_success AND NOT status EQUAL 0)
    message(FATAL_ERROR "failed (${status}): ${command}\n${out}${err}")
  elseif(NOT expect_success AND NOT status EQUAL 1)
    message(FATAL_ERROR "expected an error (exit 1), got ${status}: ${command}\n${out}${err}")
  endif()
  set(stderr "${err}" PARENT_SCOPE)
endfunction()

run(TRUE ${SAFEGLSLC} ${stages})
foreach(stage IN LISTS stages)
  run(TRUE ${SAFEGLSLC} -V --target-env vulkan1.2 ${stage} -o ${OUT}/${stage}.spv)
  run(TRUE ${SPIRV_VAL} --target-env vulkan1.2 ${OUT}/${stage}.spv)
endforeach()

# The whole pipeline in one -V run (two miss shaders: one module each) gives the same modules.
set(outputs)
foreach(stage IN LISTS stages)
  list(APPEND outputs -o ${OUT}/${stage}.program.spv)
endforeach()
run(TRUE ${SAFEGLSLC} -V --target-env vulkan1.2 ${stages} ${outputs})
foreach(stage IN LISTS stages)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/${stage}.spv ${OUT}/${stage}.program.spv RESULT_VARIABLE differs)
  if(differs)
    message(FATAL_ERROR "${stage}: the program run's module differs from the stage's own")
  endif()
endforeach()

file(READ ${DIR}/direct.sgl.rchit hit)
string(REPLACE "visibility / pdfW;" "visibility / pdfA;" wrong "${hit}")
if(wrong STREQUAL hit)
  message(FATAL_ERROR "direct.sgl.rchit no longer divides by pdfW: update the planted bug")
endif()
file(WRITE ${OUT}/wrong_measure.sgl.rchit "${wrong}")
run(FALSE ${SAFEGLSLC} ${OUT}/wrong_measure.sgl.rchit)
if(NOT stderr MATCHES "E-DIMENSION|dimension")
  message(FATAL_ERROR "the area-measure pdf was refused, but not for its dimension:\n${stderr}")
endif()
message(STATUS "ray-tracing example: ${stages} compile and validate; the area-measure pdf is refused")
