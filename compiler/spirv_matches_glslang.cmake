# SPIR-V of every bundled shader: safeglslc -G / -V writes the module that
# glslangValidator makes of safeglslc's own plain GLSL with the same options
# (byte for byte), spirv-val accepts it, and the symbol table is the one the
# GLSL run writes.
#   cmake -DSAFEGLSLC=<exe> -DVALIDATOR=<glslangValidator> -DSPIRV_VAL=<spirv-val>
#         -DROOT=<source dir> -DOUT=<scratch dir> -P spirv_matches_glslang.cmake
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})

function(run)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${OUT} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "failed (${status}): ${command}\n${out}${err}")
  endif()
endfunction()

function(same a b what)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${a} ${b} RESULT_VARIABLE differs)
  if(differs)
    message(FATAL_ERROR "${what}: ${a} and ${b} differ")
  endif()
endfunction()

# <shader> [-D...]: one case; its name in ${OUT} is the shader's plus the defines.
set(count 0)
function(check shader)
  get_filename_component(name ${shader} NAME)
  string(REPLACE ".sgl" "" plain ${name})
  string(REGEX MATCH "[a-z]+$" stage ${name})
  set(defines ${ARGN})
  string(REPLACE "-D" "_" suffix "${defines}")
  string(REPLACE ";" "" suffix "${suffix}")
  set(base ${OUT}/${plain}${suffix})
  set(compile ${SAFEGLSLC} ${shader} -I ${ROOT}/examples/shaders ${defines})
  run(${compile} -o ${base}.glsl --symbols ${base}.json)
  # -G: OpenGL; safeglslc maps locations and bindings itself, glslangValidator needs the flags.
  run(${compile} -G -o ${base}.G.spv --symbols ${base}.G.json)
  run(${VALIDATOR} -S ${stage} -G --aml --amb ${base}.glsl -o ${base}.G.expected.spv)
  same(${base}.G.spv ${base}.G.expected.spv "${name} ${defines} -G")
  run(${SPIRV_VAL} --target-env opengl4.5 ${base}.G.spv)
  same(${base}.json ${base}.G.json "${name} ${defines}: the symbol table of -G")
  # -V with relaxed rules: the bundled shaders are OpenGL GLSL (default-block uniforms).
  run(${compile} -V -R --aml --amb -o ${base}.V.spv)
  run(${VALIDATOR} -S ${stage} -V -R --aml --amb ${base}.glsl -o ${base}.V.expected.spv)
  same(${base}.V.spv ${base}.V.expected.spv "${name} ${defines} -V -R --aml --amb")
  run(${SPIRV_VAL} --target-env vulkan1.0 ${base}.V.spv)
  # A later Vulkan: glslangValidator's SPIR-V version for it (1.5).
  run(${compile} --target-env vulkan1.2 -R --aml --amb -o ${base}.V12.spv)
  run(${VALIDATOR} -S ${stage} --target-env vulkan1.2 -R --aml --amb ${base}.glsl -o ${base}.V12.expected.spv)
  same(${base}.V12.spv ${base}.V12.expected.spv "${name} ${defines} --target-env vulkan1.2")
  run(${SPIRV_VAL} --target-env vulkan1.2 ${base}.V12.spv)
  math(EXPR c "${count} + 1")
  set(count ${c} PARENT_SCOPE)
endfunction()

file(GLOB examples ${ROOT}/examples/shaders/*.sgl.*)
foreach(shader IN LISTS examples)
  check(${shader})
endforeach()
foreach(pass IN ITEMS EMISSION POINT_LIGHT AREA_SAMPLE)
  check(${ROOT}/preview/shaders/shade.sgl.frag -D${pass})
endforeach()
foreach(shader IN ITEMS scene.sgl.vert shadow_depth.sgl.vert shadow_depth.sgl.frag)
  check(${ROOT}/preview/shaders/${shader})
endforeach()
foreach(shader IN ITEMS tint.sgl.vert tint.sgl.frag)
  check(${ROOT}/compiler/testdata/${shader})
endforeach()

# Program mode (one glslang program, locations agreed across stages): valid
# modules, one per -o, and glslangValidator's default names without -o.
run(${SAFEGLSLC} -G ${ROOT}/preview/shaders/scene.sgl.vert ${ROOT}/preview/shaders/shade.sgl.frag -DPOINT_LIGHT
    -o ${OUT}/program.vert.spv -o ${OUT}/program.frag.spv)
run(${SPIRV_VAL} --target-env opengl4.5 ${OUT}/program.vert.spv)
run(${SPIRV_VAL} --target-env opengl4.5 ${OUT}/program.frag.spv)
run(${SAFEGLSLC} -G ${ROOT}/preview/shaders/shadow_depth.sgl.vert ${ROOT}/preview/shaders/shadow_depth.sgl.frag)
foreach(default_name IN ITEMS vert.spv frag.spv)
  if(NOT EXISTS ${OUT}/${default_name})
    message(FATAL_ERROR "safeglslc -G without -o wrote no ${default_name} (glslangValidator's default name)")
  endif()
  run(${SPIRV_VAL} --target-env opengl4.5 ${OUT}/${default_name})
endforeach()
message(STATUS "${count} shaders: -G, -V -R and vulkan1.2 modules equal glslangValidator's and pass spirv-val")
