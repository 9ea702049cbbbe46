# cmake --install of the public API (issue 57): libsweep.so.MAJOR with its SONAME, the headers
# of include/sweep/ (and the generated version.hpp), the CMake package (SweepConfig.cmake,
# SweepConfigVersion.cmake, SweepTargets.cmake: find_package(Sweep) gives Sweep::sweep) and
# sweep.pc for pkg-config. The package is relocatable: its files find the prefix from where
# they are, so an install into any --prefix works as installed. Components: `library` (the
# shared library) and `development` (headers, CMake package, pkg-config file).
include(CMakePackageConfigHelpers)
set(sweep_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/Sweep)

install(TARGETS sweep_library EXPORT SweepTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT library NAMELINK_COMPONENT development)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/sweep DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        COMPONENT development FILES_MATCHING PATTERN "*.hpp")
install(FILES ${PROJECT_BINARY_DIR}/include/sweep/version.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/sweep
        COMPONENT development)
install(EXPORT SweepTargets NAMESPACE Sweep:: DESTINATION ${sweep_cmake_dir} COMPONENT development)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/SweepConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/SweepConfig.cmake INSTALL_DESTINATION ${sweep_cmake_dir})
# A program built against 0.1 runs with any 0.x from 0.1 on: MAJOR is the SONAME.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/SweepConfigVersion.cmake VERSION ${PROJECT_VERSION}
                                 COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/SweepConfig.cmake ${PROJECT_BINARY_DIR}/SweepConfigVersion.cmake
        DESTINATION ${sweep_cmake_dir} COMPONENT development)

# pkg-config: prefix from the .pc file's own place (pcfiledir), as deep below it as the libdir is.
file(RELATIVE_PATH sweep_pc_to_prefix ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" sweep_pc_to_prefix "${sweep_pc_to_prefix}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/sweep.pc.in ${PROJECT_BINARY_DIR}/sweep.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/sweep.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT development)
