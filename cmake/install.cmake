# cmake --install and packaging: the executable, its manual pages and shell completion, the docs,
# the bundled data (decks/CMakeLists.txt), and the emulator's parts as a CMake package
# (find_package(parsons): parsons::cardreader, parsons::relaylogic, parsons::axes,
# parsons::decks) with their headers; CPack makes a .deb of the same tree. docs/install.md.
include(CMakePackageConfigHelpers)

set(parsons_parts cardreader axes relaylogic decks)
foreach(part IN LISTS parsons_parts)
  # Installed as libparsons_<part>.a, so no other package's libaxes.a can be mistaken for ours.
  set_target_properties(${part} PROPERTIES OUTPUT_NAME parsons_${part} EXPORT_NAME ${part})
  add_library(parsons::${part} ALIAS ${part})
  # With their subfolders (relaylogic/conditions, press, tapping: the later systems).
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${part}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/parsons/${part}
          FILES_MATCHING PATTERN "*.hpp" PATTERN "airfoils" EXCLUDE PATTERN "samples" EXCLUDE)
endforeach()

install(TARGETS parsons RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS ${parsons_parts} EXPORT parsonsTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/parsons)

set(parsons_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/parsons)
install(EXPORT parsonsTargets NAMESPACE parsons:: DESTINATION ${parsons_cmake_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/parsonsConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/parsonsConfig.cmake
                              INSTALL_DESTINATION ${parsons_cmake_dir})
# 0.x: a new minor version may change the parts' interfaces.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/parsonsConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/parsonsConfig.cmake
              ${PROJECT_BINARY_DIR}/parsonsConfigVersion.cmake
        DESTINATION ${parsons_cmake_dir})

# Written at every build by parsons_manual (cli/CMakeLists.txt).
install(DIRECTORY ${PROJECT_BINARY_DIR}/man/man1 DESTINATION ${CMAKE_INSTALL_MANDIR})
install(FILES ${PROJECT_BINARY_DIR}/completion/parsons.bash
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME parsons)
install(FILES ${PROJECT_BINARY_DIR}/completion/_parsons
        DESTINATION ${CMAKE_INSTALL_DATADIR}/zsh/vendor-completions)

install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/CHANGELOG.md
              ${PROJECT_SOURCE_DIR}/LICENSE
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs ${PROJECT_SOURCE_DIR}/examples
        DESTINATION ${CMAKE_INSTALL_DOCDIR})

# The .deb: `cpack --config build/CPackConfig.cmake` (docs/install.md). Its Depends come from
# dpkg-shlibdeps, Debian's own reading of what the executable links (libc6, libstdc++6,
# libgcc-s1, libfmt9); what building against the package needs is recommended.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME parsons)
set(CPACK_PACKAGE_VENDOR "the parsons developers")
set(CPACK_PACKAGE_CONTACT "the parsons developers <parsons@invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "emulator of the 1952 Parsons-Stulen punched-card milling-machine control")
set(CPACK_PACKAGE_DESCRIPTION
    "Feed it a deck of 80-column cards and it does what the relay cabinet of US 2,820,187 did, "
    "relay by relay: storage banks, stepping-switch counters, comparers, speed switches, the "
    "sequence and the checks. With a keypunch, a deck generator doing the 1952 airfoil "
    "cutter-offset arithmetic, card and tool-path pictures and GTKWave traces.")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "cmake, g++, libfmt-dev, nlohmann-json3-dev, libeigen3-dev")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "gtkwave")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
include(CPack)
