# safegi_add_shaders(<target>
#     SOURCES <shader>...            annotated shaders (light.sgl.frag, …)
#     [PROGRAM]                      compile them together: one symbol table, cross-stage check
#     [OUTPUT_DIRECTORY <dir>]       default: ${CMAKE_CURRENT_BINARY_DIR}/safegi_shaders/<target>
#     [INCLUDE_DIRECTORIES <dir>...] -I
#     [DEFINES <NAME[=value]>...]    -D
#     [OPTIONS <flag>...])           any other safeglslc flag (--strict, -Werror, …)
#
# Compiles annotated shaders with safeglslc at build time, before <target>;
# safeglslc's depfile (-MD) makes an edit to an #include'd file recompile them.
# A shader with errors fails the build; the messages are `file:line:col: error:`
# with absolute paths, so IDEs make them clickable. Outputs, per shader
# `<dir>/<name without .sgl>.glsl` (light.frag.glsl) and `<name>.json`; with
# PROGRAM one `<dir>/<target>.json` instead. The directory is in the target
# property SAFEGI_SHADER_DIR and the generated files in SAFEGI_SHADER_OUTPUTS.
function(safegi_add_shaders target)
  cmake_parse_arguments(ARG "PROGRAM" "OUTPUT_DIRECTORY" "SOURCES;INCLUDE_DIRECTORIES;DEFINES;OPTIONS" ${ARGN})
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "safegi_add_shaders(${target}): no SOURCES")
  endif()
  if(TARGET safeglslc)
    set(compiler $<TARGET_FILE:safeglslc>)
    set(compiler_dep safeglslc)
  elseif(TARGET SafeGI::safeglslc)
    set(compiler $<TARGET_FILE:SafeGI::safeglslc>)
    set(compiler_dep SafeGI::safeglslc)
  else()
    message(FATAL_ERROR "safegi_add_shaders(${target}): safeglslc not found (find_package(SafeGI) first)")
  endif()
  set(out_dir ${ARG_OUTPUT_DIRECTORY})
  if(NOT out_dir)
    set(out_dir ${CMAKE_CURRENT_BINARY_DIR}/safegi_shaders/${target})
  endif()
  set(flags)
  foreach(dir IN LISTS ARG_INCLUDE_DIRECTORIES)
    list(APPEND flags -I ${dir})
  endforeach()
  foreach(def IN LISTS ARG_DEFINES)
    list(APPEND flags -D ${def})
  endforeach()
  list(APPEND flags ${ARG_OPTIONS})

  set(all_outputs)
  set(program_sources)
  set(program_outputs)
  foreach(source IN LISTS ARG_SOURCES)
    get_filename_component(source ${source} ABSOLUTE)
    get_filename_component(name ${source} NAME)
    string(REPLACE ".sgl" "" name ${name})
    set(glsl ${out_dir}/${name}.glsl)
    if(ARG_PROGRAM)
      list(APPEND program_sources ${source})
      list(APPEND program_outputs -o ${glsl})
      list(APPEND all_outputs ${glsl})
    else()
      set(json ${out_dir}/${name}.json)
      add_custom_command(OUTPUT ${glsl} ${json}
        COMMAND ${CMAKE_COMMAND} -E make_directory ${out_dir}
        COMMAND ${compiler} ${flags} ${source} -o ${glsl} --symbols ${json} -MD -MF ${glsl}.d
        DEPENDS ${source} ${compiler_dep}
        DEPFILE ${glsl}.d
        COMMENT "safeglslc ${name}"
        VERBATIM)
      list(APPEND all_outputs ${glsl} ${json})
    endif()
  endforeach()
  if(ARG_PROGRAM)
    set(json ${out_dir}/${target}.json)
    add_custom_command(OUTPUT ${all_outputs} ${json}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${out_dir}
      COMMAND ${compiler} ${flags} ${program_sources} ${program_outputs} --symbols ${json} -MD -MF ${json}.d
      DEPENDS ${program_sources} ${compiler_dep}
      DEPFILE ${json}.d
      COMMENT "safeglslc program ${target}"
      VERBATIM)
    list(APPEND all_outputs ${json})
  endif()
  add_custom_target(${target}_safegi_shaders DEPENDS ${all_outputs})
  add_dependencies(${target} ${target}_safegi_shaders)
  set_property(TARGET ${target} PROPERTY SAFEGI_SHADER_DIR ${out_dir})
  set_property(TARGET ${target} APPEND PROPERTY SAFEGI_SHADER_OUTPUTS ${all_outputs})
endfunction()
