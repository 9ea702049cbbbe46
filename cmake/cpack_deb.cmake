# CPACK_PROJECT_CONFIG_FILE (cmake/install.cmake): the package's Depends, from dpkg-shlibdeps run
# on the built sweep and viewer module (CPackDebFiles.cmake in the build directory lists them).
# CPack's own CPACK_DEBIAN_PACKAGE_SHLIBDEPS does the same on the staged files but then also adds
# a postinst and postrm calling ldconfig for the module, which is private and needs none.
if(NOT CPACK_GENERATOR STREQUAL "DEB")
  return()
endif()
include(${CPACK_SWEEP_BINARY_DIR}/CPackDebFiles.cmake)
# dpkg-shlibdeps wants a debian/control to read; an empty one will do, as in CPack's own step.
set(sweep_shlibdeps_dir ${CPACK_SWEEP_BINARY_DIR}/CMakeFiles/sweep-shlibdeps)
file(WRITE ${sweep_shlibdeps_dir}/debian/control "")
execute_process(
  COMMAND dpkg-shlibdeps --ignore-missing-info -O ${SWEEP_DEB_ELF_FILES}
  WORKING_DIRECTORY ${sweep_shlibdeps_dir}
  RESULT_VARIABLE sweep_shlibdeps_result
  OUTPUT_VARIABLE sweep_shlibdeps_output
  ERROR_VARIABLE sweep_shlibdeps_error)
if(NOT sweep_shlibdeps_result EQUAL 0 OR NOT sweep_shlibdeps_output MATCHES "shlibs:Depends=([^\n]*)")
  message(FATAL_ERROR "dpkg-shlibdeps ${SWEEP_DEB_ELF_FILES} failed:\n${sweep_shlibdeps_error}")
endif()
set(CPACK_DEBIAN_PACKAGE_DEPENDS "${CMAKE_MATCH_1}")
