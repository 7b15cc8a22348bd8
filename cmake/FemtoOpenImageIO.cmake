# OpenImageIO as the imported target femto::OpenImageIO.
#
# Why not find_package(OpenImageIO): Debian 12's libopenimageio-dev ships a
# CMake package whose targets file also imports the command-line tools
# (/usr/bin/iconvert, idiff, ...) that live in openimageio-tools, and CMake
# refuses the whole package when one of them is missing. It also lists
# /usr/include/opencv4 as an include directory. femto needs only the library,
# so it is found through pkg-config (OpenImageIO.pc, in the -dev package),
# with a guarded find_package as the fallback for other systems.
find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(FEMTO_OIIO QUIET IMPORTED_TARGET GLOBAL OpenImageIO>=2.4)
endif()
if(TARGET PkgConfig::FEMTO_OIIO)
  add_library(femto::OpenImageIO ALIAS PkgConfig::FEMTO_OIIO)
  message(STATUS "OpenImageIO ${FEMTO_OIIO_VERSION} (pkg-config)")
  return()
endif()

find_package(OpenImageIO CONFIG QUIET)
if(NOT TARGET OpenImageIO::OpenImageIO)
  message(FATAL_ERROR
    "OpenImageIO 2.4 not found: install libopenimageio-dev (tools/install-deps.sh does).")
endif()
# Drop include directories that do not exist (see above).
get_target_property(_oiio_includes OpenImageIO::OpenImageIO INTERFACE_INCLUDE_DIRECTORIES)
set(_oiio_existing)
foreach(_dir ${_oiio_includes})
  if(EXISTS "${_dir}")
    list(APPEND _oiio_existing "${_dir}")
  endif()
endforeach()
set_target_properties(OpenImageIO::OpenImageIO PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_oiio_existing}")
add_library(femto::OpenImageIO ALIAS OpenImageIO::OpenImageIO)
message(STATUS "OpenImageIO ${OpenImageIO_VERSION} (CMake package)")
