# cmake --install: bin/sph, lib/libsph_core.a, include/sph/*.hpp and lib/cmake/sph, whose
# sphConfig.cmake gives find_package(sph CONFIG) the target sph::sph (verification/install).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS sph RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
set_target_properties(sph_core PROPERTIES EXPORT_NAME sph)
# The library runs only where its instruction set does (SPH_ARCH, top-level CMakeLists.txt); a
# program compiled for the same one inlines the same code of the headers the library does.
target_compile_options(sph_core INTERFACE $<INSTALL_INTERFACE:-march=${SPH_ARCH}>)
install(TARGETS sph_core EXPORT sphTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/sph DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.hpp")

set(_sph_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/sph)
install(EXPORT sphTargets NAMESPACE sph:: DESTINATION ${_sph_cmake_dir})
configure_package_config_file(${CMAKE_CURRENT_SOURCE_DIR}/cmake/sphConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/sphConfig.cmake INSTALL_DESTINATION ${_sph_cmake_dir})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/sphConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/sphConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/sphConfigVersion.cmake DESTINATION ${_sph_cmake_dir})
