# CPACK_PROJECT_CONFIG_FILE (cmake/install.cmake): each package's Depends, from dpkg-shlibdeps run
# on its built ELF files (CPackDebFiles.cmake and CPackDebComponentFiles.cmake in the build
# directory list them). CPack's own CPACK_DEBIAN_PACKAGE_SHLIBDEPS does the same on the staged
# files but then also adds a postinst and postrm calling ldconfig for the viewer module, which is
# private and needs none (libsweep0 gets ldconfig through a dpkg trigger: deb_components.cmake).
if(NOT CPACK_GENERATOR STREQUAL "DEB")
  return()
endif()
include(${CPACK_SWEEP_BINARY_DIR}/CPackDebFiles.cmake)
include(${CPACK_SWEEP_BINARY_DIR}/CPackDebComponentFiles.cmake OPTIONAL)

# The shlibs:Depends dpkg-shlibdeps finds for FILES (libsweep itself, built here, is left to the
# packages that name it).
function(sweep_shlibdeps out)
  # dpkg-shlibdeps wants a debian/control to read; an empty one will do, as in CPack's own step.
  set(dir ${CPACK_SWEEP_BINARY_DIR}/CMakeFiles/sweep-shlibdeps)
  file(WRITE ${dir}/debian/control "")
  execute_process(
    COMMAND dpkg-shlibdeps --ignore-missing-info -l${CPACK_SWEEP_BINARY_DIR}/lib -xlibsweep0 -O ${ARGN}
    WORKING_DIRECTORY ${dir}
    RESULT_VARIABLE result
    OUTPUT_VARIABLE output
    ERROR_VARIABLE error)
  if(NOT result EQUAL 0 OR NOT output MATCHES "shlibs:Depends=([^\n]*)")
    message(FATAL_ERROR "dpkg-shlibdeps ${ARGN} failed:\n${error}")
  endif()
  set(${out} "${CMAKE_MATCH_1}" PARENT_SCOPE)
endfunction()

sweep_shlibdeps(CPACK_DEBIAN_UNSPECIFIED_PACKAGE_DEPENDS ${SWEEP_DEB_ELF_FILES})
if(SWEEP_DEB_LIBRARY_FILES)
  sweep_shlibdeps(CPACK_DEBIAN_LIBRARY_PACKAGE_DEPENDS ${SWEEP_DEB_LIBRARY_FILES})
endif()
if(SWEEP_DEB_PYTHON_FILES)
  sweep_shlibdeps(python_depends ${SWEEP_DEB_PYTHON_FILES})
  math(EXPR next_minor "${SWEEP_PYTHON_MINOR} + 1")
  set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS
      "${SWEEP_DEB_LIBRARY_PACKAGE} (= ${SWEEP_DEB_VERSION}), ${python_depends}, python3 (>= 3.${SWEEP_PYTHON_MINOR}), python3 (<< 3.${next_minor}), python3-numpy")
endif()
