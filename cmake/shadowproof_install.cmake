include(CMakePackageConfigHelpers)
set(SHADOWPROOF_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/shadowproof)

# shadowproof::shadowproof (the library), shadowproof::impls (the built-in implementations
# under test, for tools built on top of the grader), shadowproof::testing (matchers and the
# property runner for the user's tests) and shadowproof::cgal (header-only CGAL interop, found
# with COMPONENTS cgal).
install(TARGETS shadowproof shadowproof_impls shadowproof_testing shadowproof_cgal EXPORT shadowproof-targets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/shadowproof DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(TARGET shadowproof_cli)
  install(TARGETS shadowproof_cli EXPORT shadowproof-targets RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  # The man page and the bash completion, generated from the command-line definitions (a test
  # keeps the committed copies equal to what the binary prints).
  install(FILES ${PROJECT_SOURCE_DIR}/src/cli/shadowproof.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
  install(FILES ${PROJECT_SOURCE_DIR}/src/cli/shadowproof.bash
          DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME shadowproof)
endif()
install(EXPORT shadowproof-targets NAMESPACE shadowproof:: DESTINATION ${SHADOWPROOF_CMAKE_DIR})

# The config file re-finds what the exported static libraries link against.
if("ogre" IN_LIST SHADOWPROOF_ENGINES)
  set(SHADOWPROOF_IMPLS_OGRE ON)
else()
  set(SHADOWPROOF_IMPLS_OGRE OFF)
endif()
foreach(engine qt osg)
  string(TOUPPER ${engine} upper)
  if(engine IN_LIST SHADOWPROOF_ENGINES)
    set(SHADOWPROOF_IMPLS_${upper} ON)
  else()
    set(SHADOWPROOF_IMPLS_${upper} OFF)
  endif()
endforeach()
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/shadowproof-config.cmake.in
  ${PROJECT_BINARY_DIR}/shadowproof-config.cmake INSTALL_DESTINATION ${SHADOWPROOF_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/shadowproof-config-version.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/shadowproof-config.cmake
              ${PROJECT_BINARY_DIR}/shadowproof-config-version.cmake
        DESTINATION ${SHADOWPROOF_CMAKE_DIR})
