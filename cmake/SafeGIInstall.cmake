# Installs SafeGI as a CMake package: find_package(SafeGI) gives SafeGI::* targets.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# safegi_install_targets(<target>... [HEADERS_FROM <dir>...])
# Adds targets to the SafeGI export set; HEADERS_FROM directories are copied
# under ${CMAKE_INSTALL_INCLUDEDIR}.
function(safegi_install_targets)
  cmake_parse_arguments(ARG "" "" "HEADERS_FROM" ${ARGN})
  # Installed names match the in-tree aliases: safegi_parser -> SafeGI::parser.
  foreach(target IN LISTS ARG_UNPARSED_ARGUMENTS)
    get_target_property(export_name ${target} EXPORT_NAME)
    if(NOT export_name AND target MATCHES "^safegi_(.+)$")
      set_target_properties(${target} PROPERTIES EXPORT_NAME ${CMAKE_MATCH_1})
    endif()
  endforeach()
  install(TARGETS ${ARG_UNPARSED_ARGUMENTS} EXPORT SafeGITargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
          INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  foreach(dir IN LISTS ARG_HEADERS_FROM)
    # Tests live beside the headers they test; only headers are installed.
    install(DIRECTORY ${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
            FILES_MATCHING PATTERN "*.hpp" PATTERN "*.h" PATTERN "*.def" PATTERN "*.sgl")
  endforeach()
  set_property(GLOBAL APPEND PROPERTY SAFEGI_EXPORTED_TARGETS ${ARG_UNPARSED_ARGUMENTS})
endfunction()

function(safegi_install_package)
  get_property(exported GLOBAL PROPERTY SAFEGI_EXPORTED_TARGETS)
  if(NOT exported)
    return()
  endif()
  set(config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/SafeGI)
  install(EXPORT SafeGITargets NAMESPACE SafeGI:: DESTINATION ${config_dir})
  configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/SafeGIConfig.cmake.in
    ${PROJECT_BINARY_DIR}/SafeGIConfig.cmake INSTALL_DESTINATION ${config_dir})
  write_basic_package_version_file(${PROJECT_BINARY_DIR}/SafeGIConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
  install(FILES ${PROJECT_BINARY_DIR}/SafeGIConfig.cmake ${PROJECT_BINARY_DIR}/SafeGIConfigVersion.cmake
          DESTINATION ${config_dir})
endfunction()
