# Every dependency is a Debian 12 package installed by scripts/install-deps.sh.

find_package(Threads REQUIRED)             # must precede glslang's config
find_package(glslang CONFIG REQUIRED)      # glslang::glslang, glslang::glslang-default-resource-limits
find_package(nlohmann_json 3 REQUIRED)
find_package(CLI11 CONFIG REQUIRED)
find_package(glm REQUIRED)                 # the typed library wraps GLM
# Debian's python3 (install-deps.sh), not one a version manager such as pyenv
# put first in PATH: find_package(Python3) then takes this one.
find_program(Python3_EXECUTABLE NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)

if(SAFEGI_BUILD_TESTS)
  find_package(GTest REQUIRED)
  find_program(SPIRV_VAL NAMES spirv-val REQUIRED)  # every SPIR-V module the tests make is validated
endif()
if(SAFEGI_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()

if(SAFEGI_BUILD_RENDERER OR SAFEGI_BUILD_GL)
  find_package(OpenImageIO CONFIG REQUIRED)
  # Debian's OpenImageIO target lists /usr/include/opencv4, which does not exist
  # unless OpenCV's headers are installed; CMake refuses missing include dirs.
  foreach(_property IN ITEMS INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
    get_target_property(_oiio_includes OpenImageIO::OpenImageIO ${_property})
    if(_oiio_includes)
      list(FILTER _oiio_includes EXCLUDE REGEX "opencv4")
      set_target_properties(OpenImageIO::OpenImageIO PROPERTIES ${_property} "${_oiio_includes}")
    endif()
  endforeach()
  find_package(OpenEXR CONFIG REQUIRED)    # the renderer writes EXR and PNG itself (image_io.cpp)
  find_package(PNG REQUIRED)
  find_package(tinyobjloader CONFIG QUIET)
  # Distributed rendering (mpirun -np N safegi-render): Debian's Open MPI, C API.
  if(SAFEGI_WITH_MPI STREQUAL "ON")
    find_package(MPI REQUIRED COMPONENTS C)
  elseif(SAFEGI_WITH_MPI STREQUAL "AUTO")
    find_package(MPI QUIET COMPONENTS C)
  elseif(NOT SAFEGI_WITH_MPI STREQUAL "OFF")
    message(FATAL_ERROR "SAFEGI_WITH_MPI must be AUTO, ON or OFF, not '${SAFEGI_WITH_MPI}'")
  endif()
  if(MPI_C_FOUND AND NOT SAFEGI_WITH_MPI STREQUAL "OFF")
    set(SAFEGI_HAVE_MPI ON)
    message(STATUS "safegi-render: distributed rendering over MPI ${MPI_C_VERSION} (${MPIEXEC_EXECUTABLE})")
  else()
    set(SAFEGI_HAVE_MPI OFF)
    message(STATUS "safegi-render: without MPI (SAFEGI_WITH_MPI=${SAFEGI_WITH_MPI})")
  endif()
endif()

if(SAFEGI_BUILD_VK)
  # Debian's libvulkan-dev: the loader and the headers (scripts/install-deps.sh).
  find_package(Vulkan QUIET)
  if(NOT Vulkan_FOUND)
    message(FATAL_ERROR "SAFEGI_BUILD_VK is ON but the Vulkan loader and headers were not found: "
                        "install libvulkan-dev (scripts/install-deps.sh), or configure with -DSAFEGI_BUILD_VK=OFF")
  endif()
endif()

if(SAFEGI_BUILD_GL)
  find_package(OpenGL REQUIRED COMPONENTS OpenGL EGL)
  find_library(OSMESA_LIBRARY NAMES OSMesa REQUIRED)
  find_path(OSMESA_INCLUDE_DIR GL/osmesa.h REQUIRED)
  find_program(GLAD_GENERATOR NAMES glad REQUIRED)
endif()
