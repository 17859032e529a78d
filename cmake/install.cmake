# cmake --install and packaging: the executable, its manual pages and shell completion, the docs,
# the bundled data (decks/CMakeLists.txt), and the emulator's parts as a CMake package
# (find_package(parsons): parsons::cardreader, parsons::relaylogic, parsons::axes,
# parsons::decks) with their headers; CPack makes two .debs of the same tree, as Debian splits
# a program from its library: `parsons` (component program) and `parsons-dev` (component dev).
# docs/install.md.
include(CMakePackageConfigHelpers)

# Who the packages name as their maintainer. The project has no mail address of its own yet, so
# the default is one that cannot be delivered (lintian's bogus-mail-host, docs/install.md); set
# it to yours when you build packages to hand on.
set(PARSONS_MAINTAINER "the parsons developers <parsons@invalid>"
    CACHE STRING "Maintainer of the .debs: Name <address>")

set(parsons_parts cardreader axes relaylogic decks)
foreach(part IN LISTS parsons_parts)
  # Installed as libparsons_<part>.a, so no other package's libaxes.a can be mistaken for ours.
  set_target_properties(${part} PROPERTIES OUTPUT_NAME parsons_${part} EXPORT_NAME ${part})
  add_library(parsons::${part} ALIAS ${part})
  # With their subfolders (relaylogic/conditions, press, tapping: the later systems).
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${part}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/parsons/${part}
          COMPONENT dev
          FILES_MATCHING PATTERN "*.hpp" PATTERN "airfoils" EXCLUDE PATTERN "samples" EXCLUDE)
endforeach()

install(TARGETS parsons RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT program)
install(TARGETS ${parsons_parts} EXPORT parsonsTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/parsons)
# `cmake --install --strip` (and CPack, CPACK_STRIP_FILES) strips the executable but keeps its
# .comment and .note sections, and leaves static libraries alone; both are finished here as
# Debian's dh_strip does it: the libraries lose their debug sections but keep the symbol table
# (they still link), and the archives are deterministic.
install(CODE "
  if(CMAKE_INSTALL_DO_STRIP)
    execute_process(COMMAND \"${CMAKE_STRIP}\" --remove-section=.comment --remove-section=.note
                            \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_BINDIR}/parsons\"
                    COMMAND_ERROR_IS_FATAL ANY)
  endif()" COMPONENT program)
install(CODE "
  if(CMAKE_INSTALL_DO_STRIP)
    foreach(part ${parsons_parts})
      execute_process(COMMAND \"${CMAKE_STRIP}\" --strip-debug --remove-section=.comment
                              --remove-section=.note --enable-deterministic-archives
                              \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/libparsons_\${part}.a\"
                      COMMAND_ERROR_IS_FATAL ANY)
    endforeach()
  endif()" COMPONENT dev)

set(parsons_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/parsons)
install(EXPORT parsonsTargets NAMESPACE parsons:: DESTINATION ${parsons_cmake_dir} COMPONENT dev)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/parsonsConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/parsonsConfig.cmake
                              INSTALL_DESTINATION ${parsons_cmake_dir})
# 0.x: a new minor version may change the parts' interfaces.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/parsonsConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/parsonsConfig.cmake
              ${PROJECT_BINARY_DIR}/parsonsConfigVersion.cmake
        DESTINATION ${parsons_cmake_dir} COMPONENT dev)

# Written at every build by parsons_manual (cli/CMakeLists.txt): the pages gzipped (gzip -9n,
# no name or time in them), as Debian installs every manual page; man reads them as they are.
install(DIRECTORY ${PROJECT_BINARY_DIR}/man/gz/man1 DESTINATION ${CMAKE_INSTALL_MANDIR}
        COMPONENT program)
install(FILES ${PROJECT_BINARY_DIR}/completion/parsons.bash
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME parsons
        COMPONENT program)
install(FILES ${PROJECT_BINARY_DIR}/completion/_parsons
        DESTINATION ${CMAKE_INSTALL_DATADIR}/zsh/vendor-completions COMPONENT program)

# Each package's /usr/share/doc/PACKAGE: the machine-readable copyright (cmake/debian/copyright)
# and changelog.gz, the package's own changelog in Debian's format (a native package's: one
# entry for this version, pointing to CHANGELOG.md; dated SOURCE_DATE_EPOCH when it is set);
# the program's holds the README, CHANGELOG.md and docs/, the library's the examples that build
# against it.
string(TIMESTAMP parsons_changelog_date "%a, %d %b %Y %H:%M:%S +0000" UTC)
file(CONFIGURE OUTPUT ${PROJECT_BINARY_DIR}/debian-changelog CONTENT
"parsons (${PROJECT_VERSION}) unstable; urgency=medium

  * parsons ${PROJECT_VERSION}. What changed is in /usr/share/doc/parsons/CHANGELOG.md.

 -- ${PARSONS_MAINTAINER}  ${parsons_changelog_date}
")
add_custom_command(OUTPUT ${PROJECT_BINARY_DIR}/changelog.gz
  COMMAND ${CMAKE_COMMAND} -DIN=${PROJECT_BINARY_DIR}/debian-changelog -DOUT=${PROJECT_BINARY_DIR}/changelog.gz
          -P ${PROJECT_SOURCE_DIR}/cmake/gzip.cmake
  DEPENDS ${PROJECT_BINARY_DIR}/debian-changelog ${PROJECT_SOURCE_DIR}/cmake/gzip.cmake
  VERBATIM)
add_custom_target(parsons_changelog ALL DEPENDS ${PROJECT_BINARY_DIR}/changelog.gz)
set(parsons_dev_docdir ${CMAKE_INSTALL_DATADIR}/doc/parsons-dev)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/CHANGELOG.md
              ${PROJECT_SOURCE_DIR}/cmake/debian/copyright
              ${PROJECT_BINARY_DIR}/changelog.gz
        DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT program)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT program)
install(FILES ${PROJECT_SOURCE_DIR}/cmake/debian/copyright ${PROJECT_BINARY_DIR}/changelog.gz
        DESTINATION ${parsons_dev_docdir} COMPONENT dev)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples DESTINATION ${parsons_dev_docdir} COMPONENT dev)

# The .debs: `cpack --config build/CPackConfig.cmake` (docs/install.md). parsons' Depends come
# from dpkg-shlibdeps, Debian's own reading of what the executable links (libc6, libstdc++6,
# libgcc-s1, libfmt9); parsons-dev depends on parsons (its data: the libraries find the bundled
# airfoils there) and on the -dev packages its headers include. Nothing recommends a compiler:
# apt installs Recommends by default.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME parsons)
set(CPACK_PACKAGE_VENDOR "the parsons developers")
set(CPACK_PACKAGE_CONTACT "${PARSONS_MAINTAINER}")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL program dev)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_ENABLE_COMPONENT_DEPENDS ON)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# Owner and group root in the data tarball, whoever runs cpack.
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)

set(CPACK_DEBIAN_PROGRAM_PACKAGE_NAME parsons)
set(CPACK_DEBIAN_PROGRAM_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PROGRAM_PACKAGE_SUGGESTS gtkwave)
# A Debian description: the synopsis, then the extended text (CPack indents it and writes " ."
# for the empty line).
string(CONCAT CPACK_DEBIAN_PROGRAM_DESCRIPTION
       "emulator of the 1952 Parsons-Stulen punched-card milling control\n"
       "Feed it a deck of 80-column cards and it does what the relay cabinet of\n"
       "US 2,820,187 did, relay by relay: storage banks, stepping-switch counters,\n"
       "comparers, speed switches, the sequence and the checks.\n"
       "\n"
       "With a keypunch, a deck generator doing the 1952 airfoil cutter-offset\n"
       "arithmetic, card and tool-path pictures and GTKWave traces.")

set(CPACK_DEBIAN_DEV_PACKAGE_NAME parsons-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
set(CPACK_COMPONENT_DEV_DEPENDS program)
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS "libfmt-dev, nlohmann-json3-dev, libeigen3-dev")
string(CONCAT CPACK_DEBIAN_DEV_DESCRIPTION
       "emulator of the 1952 Parsons-Stulen milling control - development files\n"
       "The emulator's four parts as static libraries with their headers and a CMake\n"
       "package (find_package(parsons)): the card reader and deck formats, the five\n"
       "lead-screw axes, the relay cabinet, and deck generation.\n"
       "\n"
       "Includes an example that runs a deck on the cabinet and prints every relay.")
include(CPack)
