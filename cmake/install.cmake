# Installs the libraries, headers and a CMake package so that integrators can write
#   find_package(kumite REQUIRED)
#   target_link_libraries(engine PRIVATE kumite::runtime)   # C++
#   target_link_libraries(engine PRIVATE kumite::c)         # the C API, libkumite.so, kumite.h
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS kumite_core kumite_formats kumite_runtime kumite_c EXPORT kumiteTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY core/include/ formats/include/ runtime/include/ bindings/c/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS kumite kumite-annotate RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT kumiteTargets NAMESPACE kumite:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/kumite)

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/kumiteConfig.cmake.in
  ${PROJECT_BINARY_DIR}/kumiteConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/kumite)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/kumiteConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/kumiteConfig.cmake ${PROJECT_BINARY_DIR}/kumiteConfigVersion.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/kumite)
