# Records every file the build takes from outside the tree, so that
# scripts/check-deps.sh can prove each one comes from a package that
# scripts/install-deps.sh installs (or that one of those pulls in).
#
# A machine that happens to have an extra package (CI's, a developer's) would
# otherwise hide a missing entry in install-deps.sh until a fresh machine
# fails at configure: OpenImageIO's CMake config imports /usr/bin/iconvert,
# which only openimageio-tools ships.
#
# Written at the end of configure to ${PROJECT_BINARY_DIR}/dependency-files.tsv,
# one line per file: what refers to it <TAB> the path <TAB> linked (a target
# of this project links the imported target), unlinked, or found (a cache entry).
#   imported target OpenImageIO::iconvert IMPORTED_LOCATION_NONE	/usr/bin/iconvert	unlinked
#   cache entry OSMESA_LIBRARY	/usr/lib/x86_64-linux-gnu/libOSMesa.so	found
#   package config OpenImageIO_DIR	/usr/lib/x86_64-linux-gnu/cmake/OpenImageIO	found
# Imported targets are made global (CMAKE_FIND_PACKAGE_TARGETS_GLOBAL, set
# before the first find_package) so that those a subfolder imports are seen too.

set(CMAKE_FIND_PACKAGE_TARGETS_GLOBAL ON)

# Items of a target property that name files: generator expressions are
# opened ($<LINK_ONLY:x>, $<$<CONFIG:Release>:x> both give x), flags and
# bare library names (-pthread, dl) are left to the linker, targets are
# walked on their own.
function(_safegi_paths_in value out)
  set(paths "")
  foreach(item IN LISTS value)
    # Innermost-last: $<A:$<B:x>> -> x.
    while(item MATCHES "^\\$<[^:>]*:(.*)>$")
      set(item "${CMAKE_MATCH_1}")
    endwhile()
    if(item MATCHES "\\$<" OR NOT IS_ABSOLUTE "${item}")
      continue()
    endif()
    list(APPEND paths "${item}")
  endforeach()
  set(${out} "${paths}" PARENT_SCOPE)
endfunction()

# A directory property (IMPORTED_TARGETS, BUILDSYSTEM_TARGETS) of `dir` and
# every folder below it.
function(_safegi_targets_below dir property out)
  get_property(targets DIRECTORY "${dir}" PROPERTY ${property})
  get_property(children DIRECTORY "${dir}" PROPERTY SUBDIRECTORIES)
  foreach(child IN LISTS children)
    _safegi_targets_below("${child}" ${property} more)
    list(APPEND targets ${more})
  endforeach()
  set(${out} "${targets}" PARENT_SCOPE)
endfunction()

# The imported targets that some target of this project links, directly or
# through other targets.
function(_safegi_linked_imported_targets out)
  _safegi_targets_below("${PROJECT_SOURCE_DIR}" BUILDSYSTEM_TARGETS todo)
  set(seen "")
  set(linked "")
  list(LENGTH todo remaining)
  while(remaining GREATER 0)
    list(POP_FRONT todo target)
    list(LENGTH todo remaining)
    if(target IN_LIST seen OR NOT TARGET "${target}")
      continue()
    endif()
    list(APPEND seen "${target}")
    get_target_property(imported ${target} IMPORTED)
    if(imported)
      list(APPEND linked "${target}")
    endif()
    set(dependencies "")
    get_target_property(type ${target} TYPE)
    foreach(property IN ITEMS LINK_LIBRARIES INTERFACE_LINK_LIBRARIES IMPORTED_LINK_DEPENDENT_LIBRARIES)
      if(property STREQUAL "LINK_LIBRARIES" AND (imported OR type STREQUAL "INTERFACE_LIBRARY"))
        continue()
      endif()
      get_target_property(value ${target} ${property})
      if(value)
        list(APPEND dependencies ${value})
      endif()
    endforeach()
    get_target_property(configurations ${target} IMPORTED_CONFIGURATIONS)
    foreach(configuration IN LISTS configurations)
      get_target_property(value ${target} IMPORTED_LINK_DEPENDENT_LIBRARIES_${configuration})
      if(value)
        list(APPEND dependencies ${value})
      endif()
    endforeach()
    foreach(item IN LISTS dependencies)
      while(item MATCHES "^\\$<[^:>]*:(.*)>$")
        set(item "${CMAKE_MATCH_1}")
      endwhile()
      if(TARGET "${item}")
        get_target_property(aliased "${item}" ALIASED_TARGET)
        if(aliased)
          set(item "${aliased}")
        endif()
        list(APPEND todo "${item}")
      endif()
    endforeach()
    list(LENGTH todo remaining)
  endwhile()
  set(${out} "${linked}" PARENT_SCOPE)
endfunction()

function(safegi_write_dependency_files)
  set(lines "")
  set(file_properties IMPORTED_LOCATION IMPORTED_IMPLIB IMPORTED_OBJECTS IMPORTED_LINK_INTERFACE_LIBRARIES
      IMPORTED_LINK_DEPENDENT_LIBRARIES INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES
      INTERFACE_LINK_DIRECTORIES INTERFACE_LINK_LIBRARIES INTERFACE_SOURCES)
  _safegi_targets_below("${PROJECT_SOURCE_DIR}" IMPORTED_TARGETS targets)
  list(REMOVE_DUPLICATES targets)
  _safegi_linked_imported_targets(linked)
  foreach(target IN LISTS targets)
    set(use "unlinked")
    if(target IN_LIST linked)
      set(use "linked")
    endif()
    get_target_property(configurations ${target} IMPORTED_CONFIGURATIONS)
    set(properties ${file_properties})
    foreach(configuration IN LISTS configurations)
      foreach(property IN ITEMS IMPORTED_LOCATION IMPORTED_IMPLIB IMPORTED_OBJECTS
                                IMPORTED_LINK_INTERFACE_LIBRARIES IMPORTED_LINK_DEPENDENT_LIBRARIES)
        list(APPEND properties ${property}_${configuration})
      endforeach()
    endforeach()
    foreach(property IN LISTS properties)
      get_target_property(value ${target} ${property})
      if(NOT value)
        continue()
      endif()
      _safegi_paths_in("${value}" paths)
      foreach(path IN LISTS paths)
        string(APPEND lines "imported target ${target} ${property}\t${path}\t${use}\n")
      endforeach()
    endforeach()
  endforeach()

  # find_library / find_path / find_program results and package config
  # directories (<Package>_DIR), except what lies in this tree.
  get_cmake_property(entries CACHE_VARIABLES)
  foreach(entry IN LISTS entries)
    get_property(type CACHE ${entry} PROPERTY TYPE)
    if(NOT type MATCHES "^(FILEPATH|PATH)$" OR entry STREQUAL "CMAKE_INSTALL_PREFIX")
      continue()
    endif()
    set(value "$CACHE{${entry}}")
    if(NOT IS_ABSOLUTE "${value}" OR NOT EXISTS "${value}")
      continue()  # -NOTFOUND of an optional search, or a program name
    endif()
    cmake_path(IS_PREFIX PROJECT_SOURCE_DIR "${value}" NORMALIZE in_source)
    cmake_path(IS_PREFIX PROJECT_BINARY_DIR "${value}" NORMALIZE in_build)
    if(in_source OR in_build)
      continue()
    endif()
    set(kind "cache entry")
    if(entry MATCHES "_DIR$")
      set(kind "package config")
    endif()
    string(APPEND lines "${kind} ${entry}\t${value}\tfound\n")
  endforeach()
  file(WRITE "${PROJECT_BINARY_DIR}/dependency-files.tsv" "${lines}")
endfunction()
