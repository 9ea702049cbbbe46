# cmake --install and cpack -G DEB: the sweep executable in bin/, its viewer module in
# SWEEP_GUI_MODULE_DIR (lib/sweep or lib/<multiarch>/sweep, where src/app/gui_loader.cpp looks),
# and the desktop files of packaging/: the desktop entry, the AppStream metainfo, the SWP MIME
# type, the thumbnailer, the icon, bash completion, a man page made by help2man from
# `sweep --help`, and the copyright file and Debian changelog. Nothing else has install rules, so
# tests, benchmarks and the static libraries stay out of the package.
set(sweep_packaging ${PROJECT_SOURCE_DIR}/packaging)
set(sweep_share ${CMAKE_INSTALL_DATADIR})
# The application's id: the desktop entry's name and the AppStream component id (reverse DNS, as
# AppStream requires; packaging/sweep.metainfo.xml spells it out and tests/install/ checks that
# the two agree).
set(sweep_app_id org.example.sweep)
# The package's maintainer, also the signature of packaging/changelog.
set(sweep_maintainer "Sweep developers <sweep@example.org>")

install(TARGETS sweep RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(SWEEP_GUI)
  install(TARGETS sweep_gui LIBRARY DESTINATION ${SWEEP_GUI_MODULE_DIR})
  # The thumbnailer renders through the module, so only GUI builds have one.
  install(FILES ${sweep_packaging}/sweep.thumbnailer DESTINATION ${sweep_share}/thumbnailers)
endif()
install(FILES ${sweep_packaging}/sweep.desktop DESTINATION ${sweep_share}/applications RENAME ${sweep_app_id}.desktop)
install(FILES ${sweep_packaging}/sweep.metainfo.xml DESTINATION ${sweep_share}/metainfo
        RENAME ${sweep_app_id}.metainfo.xml)
install(FILES ${sweep_packaging}/sweep-mime.xml DESTINATION ${sweep_share}/mime/packages RENAME sweep.xml)
install(FILES ${sweep_packaging}/sweep.svg DESTINATION ${sweep_share}/icons/hicolor/scalable/apps)
install(FILES ${sweep_packaging}/sweep.bash-completion DESTINATION ${sweep_share}/bash-completion/completions
        RENAME sweep)

# The man page: help2man reads `sweep --help` (which lists every subcommand) and `--version`;
# man_commands.cmake adds a COMMANDS section of each subcommand's own --help.
find_program(SWEEP_HELP2MAN help2man)
if(SWEEP_HELP2MAN)
  set(sweep_man ${PROJECT_BINARY_DIR}/sweep.1)
  add_custom_command(
    OUTPUT ${sweep_man}.gz
    COMMAND ${CMAKE_COMMAND} -DSWEEP=$<TARGET_FILE:sweep> -DOUT=${PROJECT_BINARY_DIR}/sweep-commands.h2m -P
            ${PROJECT_SOURCE_DIR}/cmake/man_commands.cmake
    COMMAND ${SWEEP_HELP2MAN} --no-info --name "spline curves and swept surfaces" --section 1
            --include ${PROJECT_BINARY_DIR}/sweep-commands.h2m --output ${sweep_man} $<TARGET_FILE:sweep>
    COMMAND gzip -9nf ${sweep_man}
    DEPENDS sweep ${PROJECT_SOURCE_DIR}/cmake/man_commands.cmake
    COMMENT "Writing the man page sweep.1.gz (help2man)")
  add_custom_target(sweep_man ALL DEPENDS ${sweep_man}.gz)
  install(FILES ${sweep_man}.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
else()
  message(STATUS "help2man not found: no man page (apt install help2man)")
endif()

# The copyright file (machine-readable: Sweep and the code of other projects compiled into it)
# and the Debian changelog, compressed as Debian policy asks (gzip -9n: no name, no timestamp).
set(sweep_doc ${sweep_share}/doc/sweep)
set(sweep_changelog ${PROJECT_BINARY_DIR}/changelog)
add_custom_command(
  OUTPUT ${sweep_changelog}.gz
  COMMAND ${CMAKE_COMMAND} -E copy ${sweep_packaging}/changelog ${sweep_changelog}
  COMMAND gzip -9nf ${sweep_changelog}
  DEPENDS ${sweep_packaging}/changelog
  COMMENT "Compressing the Debian changelog")
add_custom_target(sweep_changelog ALL DEPENDS ${sweep_changelog}.gz)
install(FILES ${sweep_packaging}/copyright ${sweep_changelog}.gz DESTINATION ${sweep_doc})

# cpack -G DEB (from the build directory): build/sweep_VERSION_ARCH.deb, its Depends from
# dpkg-shlibdeps. The MIME, desktop and icon caches are refreshed by the dpkg triggers of
# shared-mime-info, desktop-file-utils and the icon theme, so the package needs no scripts.
# CPack's own dpkg-shlibdeps step (CPACK_DEBIAN_PACKAGE_SHLIBDEPS) would also give the package a
# postinst and postrm calling ldconfig, as it does for any shared object under /usr/lib, but the
# viewer module is private (dlopen'ed by path, not on the linker's path): cmake/cpack_deb.cmake
# runs dpkg-shlibdeps on the built sweep and module instead.
# cpack does not build first (its preinstall step would build every test and benchmark, one job
# at a time): build sweep, sweep_man and sweep_changelog (or all) before running it.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY TRUE)
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME sweep)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "${sweep_maintainer}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "spline curves and swept surfaces: viewer, renderer and exporter")
# Lines of at most 80 characters (lintian's extended-description-line-too-long).
set(CPACK_PACKAGE_DESCRIPTION
    "Sweep reads SWP files (a small text format of curves and surfaces),
evaluates the curves with moving frames, builds surfaces of revolution,
generalized cylinders, birail sweeps, Bezier and B-spline patches and
subdivision surfaces, shows them in an interactive viewer, renders them
headless (OSMesa) and exports OBJ, STL and glb. Installs a desktop entry,
AppStream metainfo, a MIME type and a thumbnailer for SWP files, a man page
and bash completion.")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${sweep_maintainer}")
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS OFF)
set(sweep_deb_elf_files $<TARGET_FILE:sweep>)
if(SWEEP_GUI)
  list(APPEND sweep_deb_elf_files $<TARGET_FILE:sweep_gui>)
endif()
file(GENERATE OUTPUT ${PROJECT_BINARY_DIR}/CPackDebFiles.cmake
     CONTENT "set(SWEEP_DEB_ELF_FILES \"${sweep_deb_elf_files}\")\n")
set(CPACK_SWEEP_BINARY_DIR ${PROJECT_BINARY_DIR})
set(CPACK_PROJECT_CONFIG_FILE ${PROJECT_SOURCE_DIR}/cmake/cpack_deb.cmake)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
# One package per component, the Debian way (cmake/library.cmake): the program (sweep, the
# install rules above, CMake's Unspecified component), the shared library (libsweep0), its
# headers, CMake package and pkg-config file (libsweep-dev), and the Python module
# (python3-sweep). cmake/deb_components.cmake names and describes them.
include(cmake/deb_components.cmake)
include(CPack)
