# cpack -G DEB, split the Debian way: sweep (the program, CMake's Unspecified component),
# libsweep0 (the shared library: its SONAME in the name, shlibs and the ldconfig trigger),
# libsweep-dev (headers, the .so link, the CMake package, sweep.pc) and python3-sweep (the module
# for Debian's python3). Every package carries the copyright file and changelog in
# /usr/share/doc/PACKAGE (lintian). Depends: cmake/cpack_deb.cmake runs dpkg-shlibdeps on each
# package's ELF files.
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL Unspecified)
set(CPACK_DEBIAN_UNSPECIFIED_PACKAGE_NAME sweep)
set(CPACK_DEBIAN_UNSPECIFIED_FILE_NAME DEB-DEFAULT)
# Each package's description starts with its own synopsis: CPack would put the one summary
# before every component's description, so it is left at CPack's default, which it does not.
set(CPACK_COMPONENT_UNSPECIFIED_DESCRIPTION "${CPACK_PACKAGE_DESCRIPTION_SUMMARY}\n${CPACK_PACKAGE_DESCRIPTION}")
unset(CPACK_PACKAGE_DESCRIPTION_SUMMARY)
if(NOT SWEEP_GUI)
  return()  # no library without the GL layers (cmake/library.cmake)
endif()
list(APPEND CPACK_COMPONENTS_ALL library development)
if(TARGET sweep_python)
  list(APPEND CPACK_COMPONENTS_ALL python)
endif()
set(sweep_deb_version "${PROJECT_VERSION}")

set(CPACK_DEBIAN_LIBRARY_PACKAGE_NAME libsweep${PROJECT_VERSION_MAJOR})
set(CPACK_DEBIAN_LIBRARY_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_LIBRARY_PACKAGE_SECTION libs)
set(CPACK_COMPONENT_LIBRARY_DESCRIPTION "spline curves and swept surfaces: shared library
libsweep is Sweep's core as a library: SWP documents loaded and evaluated,
surfaces' meshes and curves' frames as arrays, edits with undo,
format-preserving saves, OBJ, STL and glb exports, headless renders and
screenshot comparison.")
# shlibs for packages built against it, and ldconfig through dpkg's trigger (no maintainer script).
set(sweep_deb_control ${PROJECT_BINARY_DIR}/deb-control/library)
file(WRITE ${sweep_deb_control}/shlibs
     "libsweep ${PROJECT_VERSION_MAJOR} libsweep${PROJECT_VERSION_MAJOR} (>= ${sweep_deb_version})\n")
file(WRITE ${sweep_deb_control}/triggers "activate-noawait ldconfig\n")
set(CPACK_DEBIAN_LIBRARY_PACKAGE_CONTROL_EXTRA "${sweep_deb_control}/shlibs;${sweep_deb_control}/triggers")
set(CPACK_DEBIAN_LIBRARY_PACKAGE_CONTROL_STRICT_PERMISSION TRUE)

set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME libsweep-dev)
set(CPACK_DEBIAN_DEVELOPMENT_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION libdevel)
set(CPACK_COMPONENT_DEVELOPMENT_DESCRIPTION "spline curves and swept surfaces: development files
The headers of Sweep's C++ API (<sweep/sweep.hpp>, C++20), the CMake package
(find_package(Sweep): Sweep::sweep) and sweep.pc for pkg-config.")
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS "libsweep${PROJECT_VERSION_MAJOR} (= ${sweep_deb_version})")

set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-sweep)
set(CPACK_DEBIAN_PYTHON_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
set(CPACK_COMPONENT_PYTHON_DESCRIPTION "spline curves and swept surfaces: Python module
The module sweep: SWP documents with their meshes and frames as numpy arrays
(views, not copies), edits, saves, exports, headless renders, and a pytest
fixture for screenshot regression.")

# The copyright file and changelog of every library package (the program's: cmake/install.cmake).
foreach(component ${CPACK_COMPONENTS_ALL})
  if(component STREQUAL "Unspecified")
    continue()
  endif()
  string(TOUPPER ${component} upper)
  install(FILES ${PROJECT_SOURCE_DIR}/packaging/copyright ${PROJECT_BINARY_DIR}/changelog.gz
          DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/${CPACK_DEBIAN_${upper}_PACKAGE_NAME} COMPONENT ${component})
endforeach()

# The .pc file lies in lib/pkgconfig, as the library does (the package is built with the plain
# libdir of an install prefix, not Debian's multiarch one): lintian's note on cross-compiling is
# overridden, with that reason.
file(WRITE ${PROJECT_BINARY_DIR}/deb-control/libsweep-dev.lintian-overrides
     "# sweep.pc lies beside libsweep in lib/, the package's plain libdir\n"
     "libsweep-dev: pkg-config-unavailable-for-cross-compilation [usr/lib/pkgconfig/sweep.pc]\n")
install(FILES ${PROJECT_BINARY_DIR}/deb-control/libsweep-dev.lintian-overrides
        DESTINATION ${CMAKE_INSTALL_DATADIR}/lintian/overrides RENAME libsweep-dev COMPONENT development)

# Which ELF files dpkg-shlibdeps reads per package (cmake/cpack_deb.cmake).
file(GENERATE OUTPUT ${PROJECT_BINARY_DIR}/CPackDebComponentFiles.cmake
     CONTENT "set(SWEEP_DEB_LIBRARY_FILES \"$<TARGET_FILE:sweep_library>\")
set(SWEEP_DEB_PYTHON_FILES \"$<$<TARGET_EXISTS:sweep_python>:$<TARGET_FILE:sweep_python>>\")
set(SWEEP_DEB_LIBRARY_PACKAGE libsweep${PROJECT_VERSION_MAJOR})
set(SWEEP_DEB_VERSION ${sweep_deb_version})
set(SWEEP_PYTHON_MINOR ${SWEEP_PYTHON_MINOR})
")
