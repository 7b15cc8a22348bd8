# `cmake --install` puts the core library, its headers, the plugins and a CMake
# package (femtoConfig.cmake) in place, so out-of-tree plugins build with
#   find_package(femto) + femto_add_plugin(name source.cpp)
include(CMakePackageConfigHelpers)
install(TARGETS femto_core EXPORT femtoTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# The core's OpenImageIO module goes beside it (the core loads it from its own folder).
install(TARGETS femto_oiio LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
# Only the public headers: the loader's stages (xml/ except loader.h) and the
# Embree wrapper (render/detail/) are the core's own business.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/core/femto DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.h" PATTERN "*.inl"
  PATTERN "detail" EXCLUDE PATTERN "xml" EXCLUDE)
install(FILES ${PROJECT_SOURCE_DIR}/src/core/femto/xml/loader.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/femto/xml)
install(EXPORT femtoTargets NAMESPACE femto:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/femto)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/femtoConfig.cmake.in
  ${PROJECT_BINARY_DIR}/femtoConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/femto)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/femtoConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/femtoConfig.cmake ${PROJECT_BINARY_DIR}/femtoConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/FemtoPlugin.cmake DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/femto)
