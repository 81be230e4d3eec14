# `cmake --install` puts the argine command, the headers and an exported CMake package in
# the prefix, so that a downstream project can find_package(argine) and link argine::argine.
include(CMakePackageConfigHelpers)
install(TARGETS argine_app RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS argine ${ARGINE_ROOM_TARGETS} argine_deps argine_warnings
        EXPORT argineTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY include/argine DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp")
install(FILES "${PROJECT_BINARY_DIR}/generated/argine/core/Version.hpp"
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/argine/core)
install(EXPORT argineTargets NAMESPACE argine::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/argine)
configure_package_config_file(cmake/argineConfig.cmake.in
  "${PROJECT_BINARY_DIR}/argineConfig.cmake"
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/argine)
write_basic_package_version_file("${PROJECT_BINARY_DIR}/argineConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/argineConfig.cmake"
              "${PROJECT_BINARY_DIR}/argineConfigVersion.cmake"
              cmake/FindExodusII.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/argine)
