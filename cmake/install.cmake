# cmake --install and cpack -G DEB: the sweep executable in bin/, its viewer module in
# SWEEP_GUI_MODULE_DIR (lib/sweep or lib/<multiarch>/sweep, where src/app/gui_loader.cpp looks),
# and the desktop files of packaging/: the desktop entry, the SWP MIME type, the thumbnailer, the
# icon, bash completion and a man page made by help2man from `sweep --help`. Nothing else has
# install rules, so tests, benchmarks and the static libraries stay out of the package.
set(sweep_packaging ${PROJECT_SOURCE_DIR}/packaging)
set(sweep_share ${CMAKE_INSTALL_DATADIR})

install(TARGETS sweep RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(SWEEP_GUI)
  install(TARGETS sweep_gui LIBRARY DESTINATION ${SWEEP_GUI_MODULE_DIR})
  # The thumbnailer renders through the module, so only GUI builds have one.
  install(FILES ${sweep_packaging}/sweep.thumbnailer DESTINATION ${sweep_share}/thumbnailers)
endif()
install(FILES ${sweep_packaging}/sweep.desktop DESTINATION ${sweep_share}/applications)
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

# cpack -G DEB (from the build directory): build/sweep_VERSION_ARCH.deb, its Depends from
# dpkg-shlibdeps. The MIME, desktop and icon caches are refreshed by the dpkg triggers of
# shared-mime-info, desktop-file-utils and the icon theme, so the package needs no scripts.
# cpack does not build first (its preinstall step would build every test and benchmark, one job
# at a time): build sweep and sweep_man (or all) before running it.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY TRUE)
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME sweep)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "Sweep developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "spline curves and swept surfaces: viewer, renderer and exporter")
set(CPACK_PACKAGE_DESCRIPTION
    "Sweep reads SWP files (a small text format of curves and surfaces), evaluates the curves with
moving frames, builds surfaces of revolution, generalized cylinders, birail sweeps, Bezier and
B-spline patches and subdivision surfaces, shows them in an interactive viewer, renders them
headless (OSMesa) and exports OBJ, STL and glb. Installs a desktop entry, a MIME type and a
thumbnailer for SWP files, a man page and bash completion.")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "Sweep developers")
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
include(CPack)
